#include "slamtune/optim/search_space.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

std::string WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("slamtune_space_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

std::string ErrorOf(const std::string& text) {
  try {
    SearchSpace::FromYaml(WriteTemp("err", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SearchSpace, PaperDefaultIsRealThenInteger) {
  const SearchSpace s = SearchSpace::PaperDefault();
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.dimensions[0].name, "loop_search_maximum_distance");
  EXPECT_EQ(s.integer_count(), 1u);
  EXPECT_NO_THROW(s.Validate("default"));
  const auto a = s.Assign({3.25, 11.4});
  EXPECT_DOUBLE_EQ(a.at("loop_match_minimum_chain_size"), 11.0);
  EXPECT_DOUBLE_EQ(a.at("loop_match_minimum_response_coarse"), 0.7);
}

TEST(SearchSpace, AroundBaseContainsTheBaseAndFixesNothing) {
  const SearchSpace toolbox = SearchSpace::AroundBase(3.0, 10);
  ASSERT_EQ(toolbox.size(), 2u);
  EXPECT_TRUE(toolbox.fixed.empty());  // p and q keep the base's values
  EXPECT_DOUBLE_EQ(toolbox.dimensions[0].lower, 2.0);
  EXPECT_DOUBLE_EQ(toolbox.dimensions[0].upper, 6.0);
  EXPECT_DOUBLE_EQ(toolbox.dimensions[1].lower, 6.0);
  EXPECT_DOUBLE_EQ(toolbox.dimensions[1].upper, 20.0);
  const SearchSpace wide = SearchSpace::AroundBase(8.5, 3);
  EXPECT_DOUBLE_EQ(wide.dimensions[0].upper, 8.5);
  EXPECT_DOUBLE_EQ(wide.dimensions[1].lower, 3.0);
  const SearchSpace narrow = SearchSpace::AroundBase(1.2, 40);
  EXPECT_DOUBLE_EQ(narrow.dimensions[0].lower, 1.2);
  EXPECT_DOUBLE_EQ(narrow.dimensions[1].upper, 40.0);
  EXPECT_NO_THROW(narrow.Validate("around base"));
}

TEST(SearchSpace, YamlOrdersIntegersLastAndKeepsFixed) {
  const SearchSpace s = SearchSpace::FromYaml(WriteTemp("ok", R"(
vary:
  loop_match_minimum_chain_size: {min: 3, max: 12, type: int}
  loop_search_maximum_distance: {min: 1.5, max: 5}
  loop_match_minimum_response_coarse: {min: 0.5, max: 0.9}
fix:
  loop_match_maximum_variance_coarse: 0.4
)"));
  ASSERT_EQ(s.size(), 3u);
  EXPECT_FALSE(s.dimensions[0].integer);
  EXPECT_FALSE(s.dimensions[1].integer);
  EXPECT_TRUE(s.dimensions[2].integer);
  EXPECT_EQ(s.dimensions[2].name, "loop_match_minimum_chain_size");
  EXPECT_DOUBLE_EQ(s.fixed.at("loop_match_maximum_variance_coarse"), 0.4);
}

TEST(SearchSpace, RejectsBadSpacesWithReadableMessages) {
  EXPECT_NE(ErrorOf("vary: {}\n").find("search space is empty"), std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  loop_search_maximum_distance: {min: 6, max: 2}\n").find("bounds reversed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  g: {min: 1.5, max: 4, type: int}\n").find("whole-number bounds"), std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  r: {min: 1, max: 4}\nextra: 1\n").find("unknown key 'extra'"), std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  r: {min: 1, max: 4, step: 1}\n").find("unknown key 'step'"), std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  r: {min: 1, max: 4}\nfix:\n  r: 2\n").find("both varied and fixed"),
            std::string::npos);
  EXPECT_NE(ErrorOf("vary:\n  r: {min: a, max: 4}\n").find("r.min must be a number"), std::string::npos);
}

TEST(SearchSpace, KeyIsCanonicalAndExact) {
  const std::map<std::string, double> a{{"b", 0.1}, {"a", 2.0}};
  EXPECT_EQ(SearchSpace::Key(a), "a=2;b=0.10000000000000001;");
  EXPECT_NE(SearchSpace::Key({{"a", 2.0}}), SearchSpace::Key({{"a", 2.0000000000000004}}));
  EXPECT_NE(SearchSpace::PaperDefault().Fingerprint(), SearchSpace().Fingerprint());
}

}  // namespace
}  // namespace slamtune::optim
