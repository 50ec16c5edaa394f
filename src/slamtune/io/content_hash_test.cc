#include "slamtune/io/content_hash.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

std::filesystem::path FreshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("slamtune_hash_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void Write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(ContentHash, KnownValueOfAFile) {
  const auto dir = FreshDir("known");
  Write(dir / "a.txt", "123456789");  // the CRC-32 check value
  EXPECT_EQ(ContentHash((dir / "a.txt").string()), "crc32:cbf43926");
}

TEST(ContentHash, SameSizeEditChangesTheHash) {
  const auto dir = FreshDir("edit");
  Write(dir / "log.clf", "FLASER 1 2.5 0 0 0 0 0 0 1.0 h 1.0\n");
  const std::string before = ContentHash((dir / "log.clf").string());
  Write(dir / "log.clf", "FLASER 1 2.6 0 0 0 0 0 0 1.0 h 1.0\n");
  EXPECT_NE(ContentHash((dir / "log.clf").string()), before);
}

TEST(ContentHash, FolderCoversNamesAndContents) {
  const auto dir = FreshDir("folder");
  Write(dir / "metadata.yaml", "x");
  Write(dir / "bag_0.db3", "y");
  const std::string before = ContentHash(dir.string());
  EXPECT_EQ(ContentHash(dir.string()), before);
  Write(dir / "bag_0.db3", "z");
  EXPECT_NE(ContentHash(dir.string()), before);
}

TEST(ContentHash, MissingFileIsAnInputError) {
  EXPECT_THROW(ContentHash((FreshDir("missing") / "none.clf").string()), InputError);
}

TEST(RequireSameContent, ChangedFileIsRefusedNamingIt) {
  const auto dir = FreshDir("require");
  const std::string log = (dir / "log.clf").string(), params = (dir / "p.yaml").string();
  Write(log, "abc");
  Write(params, "r: 2");
  const auto recorded = ContentHashes({{"log", log}, {"params", params}, {"relations", ""}});
  EXPECT_EQ(recorded.size(), 2u);
  EXPECT_NO_THROW(RequireSameContent(recorded, {{"log", log}, {"params", params}}));
  Write(params, "r: 3");
  try {
    RequireSameContent(recorded, {{"log", log}, {"params", params}});
    FAIL() << "a changed file was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(params + ": changed since the run started (content crc32:", 0), 0u)
        << e.what();
  }
}

TEST(RequireSameContent, FilesWithoutARecordedHashAreNotChecked) {
  const auto dir = FreshDir("old");
  Write(dir / "log.clf", "abc");
  EXPECT_NO_THROW(RequireSameContent({}, {{"log", (dir / "log.clf").string()}}));
}

}  // namespace
}  // namespace slamtune::io
