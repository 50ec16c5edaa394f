#include "slamtune/optim/search_space.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::optim {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// One file per test and name: ctest runs the tests of this file in parallel processes.
std::string WriteTemp(const std::string& name, const std::string& text) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto path = std::filesystem::temp_directory_path() / ("slamtune_space_" + test + "_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

InputError ErrorFrom(const std::string& name, const std::string& text) {
  try {
    SearchSpace::FromYaml(WriteTemp(name, text));
  } catch (const InputError& e) {
    return e;
  }
  return InputError("no error");
}
std::string MessageOf(const std::string& name, const std::string& text) { return ErrorFrom(name, text).message(); }
std::size_t ErrorLine(const std::string& name, const std::string& text) { return ErrorFrom(name, text).line(); }

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

TEST(SearchSpace, LoopKeepsAroundBasesRangesOnCentimetreSteps) {
  slam::MapperParams base;  // slam_karto: r 4 m, g 10
  SearchSpace s = SearchSpace::Loop(base);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.dimensions[0].name, "loop_search_maximum_distance");
  EXPECT_DOUBLE_EQ(s.dimensions[0].lower, 2.0);
  EXPECT_DOUBLE_EQ(s.dimensions[0].upper, 6.0);
  EXPECT_DOUBLE_EQ(s.dimensions[0].step, 0.01);
  EXPECT_TRUE(s.dimensions[1].integer);
  EXPECT_DOUBLE_EQ(s.dimensions[1].lower, 6.0);
  EXPECT_DOUBLE_EQ(s.dimensions[1].upper, 20.0);
  EXPECT_DOUBLE_EQ(s.Assign({3.9497659254462367, 12.0}).at("loop_search_maximum_distance"), 3.95);
  // A base off the centimetre grid stays a point of the space; ranges widen to hold a base outside them.
  base.loop_search_maximum_distance = 8.123;
  base.loop_match_minimum_chain_size = 3;
  s = SearchSpace::Loop(base);
  EXPECT_DOUBLE_EQ(s.dimensions[0].upper, 8.123);
  EXPECT_DOUBLE_EQ(s.dimensions[1].lower, 3.0);
  EXPECT_DOUBLE_EQ(s.Assign({8.123, 3.0}).at("loop_search_maximum_distance"), 8.123);
  EXPECT_NO_THROW(s.Validate("loop"));
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

TEST(SearchSpace, RefusesWhatCannotBeSearchedNamingTheLine) {
  EXPECT_EQ(MessageOf("bool", "vary:\n  do_loop_closing: {min: 0, max: 1}\n"),
            "'do_loop_closing' is a bool parameter: only numbers can be searched (set it with fix: or --set)");
  EXPECT_EQ(MessageOf("intreal", "vary:\n  loop_match_minimum_chain_size: {min: 3, max: 12, type: real}\n"),
            "'loop_match_minimum_chain_size' is an integer parameter: its type must be int");
  EXPECT_EQ(MessageOf("typo", "vary:\n  loop_search_maximum_distanse: {min: 2, max: 6}\n"),
            "unknown mapper parameter 'loop_search_maximum_distanse' (did you mean 'loop_search_maximum_distance'?)");
  EXPECT_EQ(
      ErrorLine("typo2", "vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n  minimum_travel: 0.1\n"), 4u);
  // An integer parameter without a type is searched as an integer.
  const SearchSpace s = SearchSpace::FromYaml(WriteTemp("inttype", "vary:\n  scan_buffer_size: {min: 5, max: 40}\n"));
  EXPECT_TRUE(s.dimensions[0].integer);
}

TEST(SearchSpace, CheckAgainstTheBaseNamesTheValueAndLine) {
  const std::string path = WriteTemp("against", "vary:\n  loop_search_maximum_distance: {min: -1, max: 6}\n");
  const SearchSpace neg = SearchSpace::FromYaml(path);
  try {
    CheckSpaceAgainst(neg, slam::MapperParams{}, path);
    FAIL() << "a negative r was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_THAT(e.message(), ::testing::HasSubstr("loop_search_maximum_distance = -1 is out of range"));
  }
  const std::string g0 = WriteTemp("g0",
                                   "vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n"
                                   "  loop_match_minimum_chain_size: 0\n");
  try {
    CheckSpaceAgainst(SearchSpace::FromYaml(g0), slam::MapperParams{}, g0);
    FAIL() << "g = 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4u);
  }
  // Fixed values that only fit together with the varied one are taken.
  const std::string matcher = WriteTemp("matcher",
                                        "vary:\n  loop_search_maximum_distance: {min: 2, max: 6}\nfix:\n"
                                        "  correlation_search_space_dimension: 0.6\n"
                                        "  correlation_search_space_resolution: 0.1\n"
                                        "  correlation_search_space_smear_deviation: 0.2\n");
  EXPECT_NO_THROW(CheckSpaceAgainst(SearchSpace::FromYaml(matcher), slam::MapperParams{}, matcher));
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

// A folder or a missing file given as --space is refused naming it, as every text input is
// (common/text_file.h), not with the stream library's own words.
TEST(SearchSpace, AFolderOrAMissingFileIsRefusedNamingIt) {
  const auto folder = std::filesystem::temp_directory_path() / "slamtune_space_folder";
  std::filesystem::create_directories(folder);
  EXPECT_EQ(ErrorMessageOf([&] { SearchSpace::FromYaml(folder.string()); }),
            folder.string() + ": cannot open: is a directory");
  EXPECT_EQ(ErrorMessageOf([&] { SearchSpace::FromYaml((folder / "none.yaml").string()); }),
            (folder / "none.yaml").string() + ": cannot open: no such file");
}

TEST(SearchSpace, KeysAndTypesThatAreNotTextAreInputErrors) {
  EXPECT_EQ(ErrorMessageOf([] { SearchSpace::FromYaml(WriteTemp("err", "[vary]: 1\n")); }),
            WriteTemp("err", "[vary]: 1\n") + ":1: a top-level key must be plain text, not a YAML sequence");
  EXPECT_EQ(MessageOf("key", "vary:\n  {a: 1}: {min: 1, max: 2}\n"),
            "a parameter name must be plain text, not a YAML map");
  EXPECT_EQ(MessageOf("field", "vary:\n  scan_buffer_size: {min: 1, max: 2, [t]: 1}\n"),
            "a key of 'scan_buffer_size' must be plain text, not a YAML sequence");
  EXPECT_EQ(MessageOf("type", "vary:\n  scan_buffer_size: {min: 1, max: 2, type: {int: 1}}\n"),
            "scan_buffer_size.type must be plain text, not a YAML map");
  EXPECT_EQ(MessageOf("fix", "vary:\n  scan_buffer_size: {min: 1, max: 2}\nfix:\n  [a, b]: 1\n"),
            "a parameter name must be plain text, not a YAML sequence");
}

TEST(SearchSpace, RejectsBadSpacesWithReadableMessages) {
  EXPECT_THAT([] { SearchSpace::FromYaml(WriteTemp("err", "vary: {}\n")); },
              ThrowsMessage<InputError>(HasSubstr("search space is empty")));
  EXPECT_THAT(
      [] { SearchSpace::FromYaml(WriteTemp("err", "vary:\n  loop_search_maximum_distance: {min: 6, max: 2}\n")); },
      ThrowsMessage<InputError>(HasSubstr("bounds reversed")));
  EXPECT_THAT(
      [] {
        SearchSpace::FromYaml(
            WriteTemp("err", "vary:\n  loop_match_minimum_chain_size: {min: 1.5, max: 4, type: int}\n"));
      },
      ThrowsMessage<InputError>(HasSubstr("whole-number bounds")));
  EXPECT_THAT(
      [] {
        SearchSpace::FromYaml(WriteTemp("err", "vary:\n  loop_search_maximum_distance: {min: 1, max: 4}\nextra: 1\n"));
      },
      ThrowsMessage<InputError>(HasSubstr("unknown key 'extra'")));
  EXPECT_THAT(
      [] {
        SearchSpace::FromYaml(WriteTemp("err", "vary:\n  loop_search_maximum_distance: {min: 1, max: 4, stride: 1}\n"));
      },
      ThrowsMessage<InputError>(HasSubstr("unknown key 'stride'")));
  EXPECT_EQ(MessageOf("step", "vary:\n  loop_search_maximum_distance: {min: 1, max: 4, step: 5}\n"),
            "'loop_search_maximum_distance': step 5 must be > 0 and at most max - min = 3");
  EXPECT_EQ(MessageOf("intstep", "vary:\n  scan_buffer_size: {min: 5, max: 40, step: 2.5}\n"),
            "'scan_buffer_size': an int parameter needs a whole-number step, got 2.5");
  EXPECT_THAT(
      [] {
        SearchSpace::FromYaml(WriteTemp(
            "err",
            "vary:\n  loop_search_maximum_distance: {min: 1, max: 4}\nfix:\n  loop_search_maximum_distance: 2\n"));
      },
      ThrowsMessage<InputError>(HasSubstr("both varied and fixed")));
  EXPECT_THAT(
      [] { SearchSpace::FromYaml(WriteTemp("err", "vary:\n  loop_search_maximum_distance: {min: a, max: 4}\n")); },
      ThrowsMessage<InputError>(HasSubstr("loop_search_maximum_distance.min must be a number")));
}

TEST(SearchSpace, StepsPutEveryValueOnTheLatticeWithinBounds) {
  const SearchSpace s = SearchSpace::FromYaml(WriteTemp("steps", R"(
vary:
  correlation_search_space_dimension: {min: 0.3, max: 1.61, step: 0.02}
  scan_buffer_size: {min: 5, max: 40, step: 5}
)"));
  const Dimension& window = s.dimensions[0];
  EXPECT_DOUBLE_EQ(window.step, 0.02);
  EXPECT_EQ(window.ValueOf(0.3), 0.3);
  EXPECT_EQ(window.ValueOf(0.3509), 0.36);  // nearest step, written as the decimal
  EXPECT_EQ(window.ValueOf(0.3489), 0.34);
  EXPECT_EQ(window.ValueOf(1.61), 1.6);  // the last step below the bound
  EXPECT_EQ(window.ValueOf(-3.0), 0.3);
  // Every value is an even number of 1 cm cells, as the engine requires of the window.
  for (double x = 0.3; x <= 1.61; x += 0.0037) {
    const double cells = window.ValueOf(x) / 0.01;
    EXPECT_NEAR(cells, 2.0 * std::round(cells / 2.0), 1e-9) << x;
  }
  const auto a = s.Assign({0.777, 17.4});
  EXPECT_EQ(a.at("correlation_search_space_dimension"), 0.78);
  EXPECT_EQ(a.at("scan_buffer_size"), 15.0);
  // Offspring closer than a step are the same parameter set, hence one database key.
  EXPECT_EQ(SearchSpace::Key(s.Assign({0.771, 16.0})), SearchSpace::Key(s.Assign({0.789, 14.0})));
  // A step is part of the fingerprint; a space without steps keeps the fingerprint it had.
  SearchSpace no_step = s;
  for (Dimension& d : no_step.dimensions) d.step = 0.0;
  EXPECT_NE(s.Fingerprint(), no_step.Fingerprint());
  EXPECT_EQ(no_step.Fingerprint(),
            "vary:correlation_search_space_dimension[0.29999999999999999,1.6100000000000001]real;"
            "scan_buffer_size[5,40]int;fix:");
}

TEST(SearchSpace, FrontEndHoldsTheBaseAndEveryBoundIsAValidConfiguration) {
  for (const char* preset : {"slam_karto", "slam_toolbox"}) {
    const slam::MapperParams base = slam::MapperParams::Preset(preset);
    const SearchSpace s = SearchSpace::FrontEnd(base);
    EXPECT_NO_THROW(s.Validate("front-end")) << preset;
    EXPECT_NO_THROW(CheckSpaceAgainst(s, base, "front-end")) << preset;
    EXPECT_TRUE(s.fixed.empty());
    for (const char* name :
         {"correlation_search_space_dimension", "coarse_search_angle_offset", "minimum_travel_distance",
          "minimum_travel_heading", "correlation_search_space_smear_deviation", "scan_buffer_size",
          "link_match_minimum_response_fine", "loop_search_maximum_distance", "loop_match_minimum_chain_size",
          "loop_match_minimum_response_coarse", "loop_match_maximum_variance_coarse"}) {
      const auto d =
          std::find_if(s.dimensions.begin(), s.dimensions.end(), [&](const Dimension& x) { return x.name == name; });
      ASSERT_NE(d, s.dimensions.end()) << name;
      const double value = slam::GetNumeric(base, name);
      EXPECT_LE(d->lower, value) << preset << " " << name;
      EXPECT_GE(d->upper, value) << preset << " " << name;
      EXPECT_GT(d->step, 0.0) << name;
      EXPECT_EQ(d->ValueOf(value), value) << preset << " " << name << ": the base is on the lattice";
    }
    // Random points of the space are configurations the engine accepts.
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<double> x;
      for (const Dimension& d : s.dimensions) x.push_back(std::uniform_real_distribution<>(d.lower, d.upper)(rng));
      slam::MapperParams probe = base;
      EXPECT_NO_THROW(slam::SetNumerics(probe, s.Assign(x))) << preset << " trial " << trial;
    }
  }
}

TEST(SearchSpace, KeyIsCanonicalAndExact) {
  const std::map<std::string, double> a{{"b", 0.1}, {"a", 2.0}};
  EXPECT_EQ(SearchSpace::Key(a), "a=2;b=0.10000000000000001;");
  EXPECT_NE(SearchSpace::Key({{"a", 2.0}}), SearchSpace::Key({{"a", 2.0000000000000004}}));
  EXPECT_NE(SearchSpace::PaperDefault().Fingerprint(), SearchSpace().Fingerprint());
}

}  // namespace
}  // namespace slamtune::optim

namespace slamtune::optim {
namespace {

TEST(SearchSpaceFromFlags, BuildsTheSpaceAYamlFileWouldHold) {
  const SearchSpace s = SearchSpace::FromFlags({"g=6:20", "r=2:6:0.01"}, {"p=0.7"});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.dimensions[0].name, "loop_search_maximum_distance");  // reals first
  EXPECT_FALSE(s.dimensions[0].integer);
  EXPECT_DOUBLE_EQ(s.dimensions[0].step, 0.01);
  EXPECT_EQ(s.dimensions[1].name, "loop_match_minimum_chain_size");
  EXPECT_TRUE(s.dimensions[1].integer);
  EXPECT_EQ(s.dimensions[1].lower, 6.0);
  EXPECT_EQ(s.fixed.at("loop_match_minimum_response_coarse"), 0.7);
}

TEST(SearchSpaceFromFlags, RefusesMalformedEntriesNamingTheFlag) {
  for (const std::vector<std::string>& vary : std::vector<std::vector<std::string>>{
           {"r"}, {"r=2"}, {"r=2:3:4:5"}, {"=2:3"}, {"r=a:3"}, {"r=2:3:nan"}, {"r=3:2"}, {"r=2:6", "r=3:4"}}) {
    EXPECT_THROW(SearchSpace::FromFlags(vary, {}), InputError) << vary[0];
  }
  EXPECT_THROW(SearchSpace::FromFlags({"r=2:6"}, {"p"}), InputError);
  EXPECT_THROW(SearchSpace::FromFlags({"r=2:6"}, {"r=3"}), InputError);  // varied and fixed
  EXPECT_THROW(SearchSpace::FromFlags({"r=2:6"}, {"p=0.7", "p=0.8"}), InputError);
  EXPECT_THROW(SearchSpace::FromFlags({"use_scan_matching=0:1"}, {}), InputError);  // a bool
  try {
    SearchSpace::FromFlags({"r=2:x"}, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--vary loop_search_maximum_distance MAX: 'x' is not a number");
  }
}

TEST(SearchSpace, VariesMapSamplingWhenNodeSpacingRangeOrResolutionAreSearched) {
  const slam::MapperParams base;
  EXPECT_FALSE(SearchSpace::Loop(base).VariesMapSampling());
  EXPECT_FALSE(SearchSpace::PaperDefault().VariesMapSampling());
  EXPECT_TRUE(SearchSpace::FrontEnd(base).VariesMapSampling());
  for (const char* name : {"minimum_travel_distance", "minimum_travel_heading", "minimum_time_interval",
                           "max_laser_range", "min_laser_range", "resolution"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(SearchSpace::FromFlags({std::string(name) + "=0.1:0.5"}, {}).VariesMapSampling());
  }
  // Fixing one does not vary it.
  EXPECT_FALSE(SearchSpace::FromFlags({"r=2:6"}, {"minimum_travel_distance=0.5"}).VariesMapSampling());
}

TEST(FullParamName, ExpandsTheSeedPapersShortNamesOnly) {
  EXPECT_EQ(FullParamName("r"), "loop_search_maximum_distance");
  EXPECT_EQ(FullParamName("q"), "loop_match_maximum_variance_coarse");
  EXPECT_EQ(FullParamName("resolution"), "resolution");
}

}  // namespace
}  // namespace slamtune::optim
