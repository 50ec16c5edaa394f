#include "slamtune/io/relations.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "slamtune/common/error.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {
namespace {

// Column names of the Freiburg relations format (Kümmerle et al. 2009, §"Benchmark data").
constexpr const char* kRelationColumns[] = {"t1", "t2", "x", "y", "z", "roll", "pitch", "yaw"};
constexpr std::size_t kNumRelationColumns = 8;

}  // namespace

std::vector<Relation> ReadRelations(const std::string& path) {
  LineReader reader(path);
  std::vector<Relation> relations;
  std::vector<std::string_view> fields;
  std::string_view line;
  while (reader.Next(&line)) {
    if (IsBlankOrComment(line)) continue;
    SplitFields(line, &fields);
    if (fields.size() != kNumRelationColumns) {
      throw InputError(path, reader.line_number(),
                       "expected 8 columns (t1 t2 x y z roll pitch yaw), found " + std::to_string(fields.size()) +
                           (reader.unterminated() ? " (truncated last line?)" : ""));
    }
    double v[kNumRelationColumns];
    for (std::size_t i = 0; i < kNumRelationColumns; ++i)
      v[i] = RequireFinite(reader, fields[i], i + 1, kRelationColumns[i]);
    Relation relation;
    relation.t1 = v[0];
    relation.t2 = v[1];
    relation.delta = Pose2{v[2], v[3], v[7]};  // 2D: z, roll and pitch are ignored
    relation.line = reader.line_number();
    relations.push_back(relation);
  }
  return relations;
}

void WriteRelations(const std::string& path, const std::vector<Relation>& relations) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  for (const Relation& r : relations) {
    std::fprintf(file, "%s %s %s %s 0 0 0 %s\n", FormatExact(r.t1).c_str(), FormatExact(r.t2).c_str(),
                 FormatExact(r.delta.x).c_str(), FormatExact(r.delta.y).c_str(), FormatExact(r.delta.theta).c_str());
  }
  const bool failed = std::ferror(file) != 0;
  if (std::fclose(file) != 0 || failed) throw InputError(path, 0, "cannot write: error while writing the file");
}

}  // namespace slamtune::io
