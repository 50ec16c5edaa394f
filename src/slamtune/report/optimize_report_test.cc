#include "slamtune/report/optimize_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/map_image.h"
#include "slamtune/report/figures/front_end_map.h"
#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

// A new, empty folder of its own for each call: concurrent test runs never share one.
fs::path FreshDir(const std::string& name) { return slamtune::testing::UniqueTempDir("report_" + name); }

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(WriteOptimizeReport, WritesEveryFileWithGroundTruth) {
  const fs::path dir = FreshDir("gt");
  const auto summary = WriteOptimizeReport(testing::FakeOptimizeResult(true), dir.string());
  for (const char* name : {"results.json",
                           "table3_best_worst_params.csv",
                           "table4_6_objectives.csv",
                           "table7_loop_closures.csv",
                           "table8_loop_scans.csv",
                           "table9_10_errors.csv",
                           "evaluations.csv",
                           "maps_side_by_side.png",
                           "map_recommended.pgm",
                           "map_recommended.yaml",
                           "map_knee.pgm",
                           "map_knee.yaml",
                           "map_worst.pgm",
                           "map_worst.yaml",
                           "population_gen1.png",
                           "population_gen3.png",
                           "population_gen5.png",
                           "population_evolution.png",
                           "objective_vs_error.png",
                           "map_recommended.png",
                           "map_knee.png",
                           "map_worst.png",
                           "map_default.png",
                           "parameter_space.png",
                           "history.png",
                           "slices_occupied_ratio.png",
                           "slices_corner_pixels.png",
                           "slices_enclosed_areas.png",
                           "report.html"}) {
    EXPECT_TRUE(fs::exists(dir / name)) << name;
    EXPECT_THAT(summary.files, ::testing::Contains(std::string(name)));
  }
  EXPECT_FALSE(fs::exists(dir / "map_default.pgm"));  // its map was not rendered
  EXPECT_EQ(summary.maps_written, 3);
  // Every PNG decodes; the population figure is a 1 x 3 row of panels.
  const cv::Mat population = cv::imread((dir / "population_gen1.png").string());
  ASSERT_FALSE(population.empty());
  EXPECT_GT(population.cols, 3 * 520);
  EXPECT_LT(population.rows, 2 * 420);
  // The written map reads back as the candidate's map.
  const io::MapImage back = io::ReadMap((dir / "map_knee.yaml").string());
  EXPECT_EQ(back.width, testing::FakeOptimizeResult(true).Find("knee")->map.width);
  EXPECT_EQ(back.pixels, testing::FakeOptimizeResult(true).Find("knee")->map.pixels);
}

TEST(WriteOptimizeReport, ResultsJsonHasTheStableKeysAndValues) {
  const fs::path dir = FreshDir("json");
  WriteOptimizeReport(testing::FakeOptimizeResult(true), dir.string());
  const auto j = nlohmann::json::parse(ReadWholeFile(dir / "results.json"));
  for (const char* key : {"recommended", "knee", "worst", "default", "evaluations", "cache_hits", "wall_s", "verdict",
                          "recommended_share", "lowest_error", "settings", "search_space"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  const auto& rec = j["recommended"];
  EXPECT_DOUBLE_EQ(rec["params"]["loop_search_maximum_distance"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(rec["params"]["loop_match_minimum_chain_size"].get<double>(), 12.0);
  const auto expected = testing::FakeRecord(3.0, 12, 0.1, true);
  EXPECT_DOUBLE_EQ(rec["figures"]["occupied_ratio"].get<double>(), expected.occupied_ratio);
  EXPECT_DOUBLE_EQ(rec["figures"]["corner_pixels"].get<double>(), expected.corner_pixels);
  EXPECT_DOUBLE_EQ(rec["figures"]["enclosed_areas"].get<double>(), expected.enclosed_areas);
  // Every figure of the table, the derived ones too, under "figures".
  EXPECT_EQ(rec["figures"].size(), optim::RecordFigures().size());
  EXPECT_DOUBLE_EQ(rec["figures"]["unbacked_hits"].get<double>(),
                   optim::FigureValue(optim::FigureNamed("unbacked_hits"), expected));
  EXPECT_EQ(rec["loop_closures"].get<int>(), expected.loop_closures);
  EXPECT_EQ(rec["loop_scans"].get<std::vector<int>>(), expected.loop_scans);
  EXPECT_DOUBLE_EQ(rec["gt_error"]["trans_mean_m"].get<double>(), expected.trans_mean_m);
  EXPECT_DOUBLE_EQ(rec["gt_error"]["rot_std_deg"].get<double>(), expected.rot_std_deg);
  EXPECT_EQ(rec["gt_error"]["relations_used"].get<int>(), 250);
  EXPECT_EQ(j["evaluations"].get<int>(), 13);
  EXPECT_EQ(j["cache_hits"].get<int>(), 27);
  EXPECT_DOUBLE_EQ(j["wall_s"].get<double>(), 321.5);
  EXPECT_EQ(j["recommended_share"].get<int>(), 5);
  EXPECT_EQ(j["lowest_error"].get<std::string>(), "knee");
  EXPECT_EQ(j["settings"]["population"].get<int>(), 8);
  EXPECT_EQ(j["search_space"]["dimensions"][1]["type"].get<std::string>(), "int");
  // 12 distinct parameter sets ran with ground truth; error rises with eta, so rho(eta) = +1.
  EXPECT_EQ(j["error_correlation"]["parameter_sets"].get<int>(), 12);
  EXPECT_DOUBLE_EQ(j["error_correlation"]["occupied_ratio"]["rho"].get<double>(), 1.0);
  EXPECT_LT(j["error_correlation"]["enclosed_areas"]["rho"].get<double>(), 0.0);
}

TEST(WriteOptimizeReport, ShowsWhereTheBaseConfigurationsFrontEndBroke) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  optim::BaseFrontEnd fe;
  for (int i = 0; i < 60; ++i) {
    slam::SequentialMatchStep s;
    s.log_index = 3 * i;
    s.time = 0.6 * i;
    s.response = 0.85;
    fe.steps.push_back(s);
  }
  fe.steps[20].at_heading_edge = true;  // a spin the search could not follow
  fe.steps[20].dtheta = 0.34;
  fe.steps[20].response = 0.08;
  fe.evidence = slam::AssessFrontEnd(fe.steps);
  ASSERT_TRUE(fe.evidence.points_at_front_end());
  fe.choice = "search space: front-end (...)";
  // The base run's map and a pose per log scan (a straight line across the room).
  fe.map = testing::FakeMap(60, 40);
  for (int i = 0; i < 180; ++i) fe.trajectory.push_back({0.1 * i, {-0.8 + 0.01 * i, -1.0, 0.0}});
  result.base_front_end = fe;
  const fs::path dir = FreshDir("fe");
  const auto summary = WriteOptimizeReport(result, dir.string());
  EXPECT_THAT(summary.files, ::testing::Contains(std::string("front_end.png")));
  EXPECT_FALSE(cv::imread((dir / "front_end.png").string()).empty());
  // Where it broke, on the map: the same image RenderFrontEndMap draws for `slamtune run`.
  EXPECT_THAT(summary.files, ::testing::Contains(std::string("front_end_map.png")));
  const cv::Mat where = cv::imread((dir / "front_end_map.png").string());
  ASSERT_FALSE(where.empty());
  const cv::Mat expected = RenderFrontEndMap(fe.map, fe.trajectory, fe.steps, fe.evidence);
  ASSERT_EQ(where.size(), expected.size());
  EXPECT_EQ(cv::norm(where, expected, cv::NORM_INF), 0.0);
  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("Front end of the base configuration"));
  EXPECT_THAT(html, HasSubstr("front_end_map.png"));
  // On the first screen, beside the recommended map, before any section; and in its own section.
  EXPECT_LT(html.find("front_end_map.png"), html.find("<h2"));
  EXPECT_LT(html.find("Front end of the base configuration"),
            html.find("front_end_map.png", html.find("Front end of the base configuration")));
  EXPECT_THAT(html, HasSubstr("60-60"));  // the break's log scans
  const auto j = nlohmann::json::parse(ReadWholeFile(dir / "results.json"));
  EXPECT_EQ(j["base_front_end"]["breaks"].get<int>(), 1);
  EXPECT_EQ(j["base_front_end"]["stretches"][0]["first_log_index"].get<int>(), 60);
  // Without a base run (a --space given, or a resumed run) there is no such section.
  const fs::path plain = FreshDir("fe_plain");
  WriteOptimizeReport(testing::FakeOptimizeResult(false), plain.string());
  EXPECT_FALSE(fs::exists(plain / "front_end.png"));
  EXPECT_FALSE(fs::exists(plain / "front_end_map.png"));
  EXPECT_THAT(ReadWholeFile(plain / "report.html"), Not(HasSubstr("Front end of the base configuration")));
  // A base run that failed before it built a map: the plot, no map.
  fe.map = io::MapImage{};
  result.base_front_end = fe;
  const fs::path no_map = FreshDir("fe_no_map");
  WriteOptimizeReport(result, no_map.string());
  EXPECT_TRUE(fs::exists(no_map / "front_end.png"));
  EXPECT_FALSE(fs::exists(no_map / "front_end_map.png"));
}

TEST(WriteOptimizeReport, HistoryEquivalentRegionAndEveryEvaluation) {
  const fs::path dir = FreshDir("history");
  const optim::OptimizeResult result = testing::FakeOptimizeResult(true);
  WriteOptimizeReport(result, dir.string());
  // results.json: one history entry per generation, 0..5, and the equivalent region.
  const auto j = nlohmann::json::parse(ReadWholeFile(dir / "results.json"));
  ASSERT_EQ(j["history"]["generations"].size(), 6u);
  EXPECT_DOUBLE_EQ(j["history"]["reference"].get<double>(), 1.1);
  const auto& g0 = j["history"]["generations"][0];
  EXPECT_EQ(g0["generation"].get<int>(), 0);
  EXPECT_EQ(g0["failed"].get<int>(), 1);
  EXPECT_DOUBLE_EQ(g0["hypervolume"].get<double>(), result.history.generations[0].hypervolume);
  EXPECT_DOUBLE_EQ(g0["best"]["corner_pixels"].get<double>(), result.history.generations[0].best[1]);
  EXPECT_EQ(j["history"]["normalised_by"]["corner_pixels"].size(), 2u);
  const auto& region = j["equivalent_region"];
  EXPECT_EQ(region["members"].get<int>(), 4);
  EXPECT_EQ(region["evaluated"].get<int>(), 12);
  EXPECT_DOUBLE_EQ(region["tolerance"].get<double>(), 0.02);
  EXPECT_EQ(region["ranges"]["loop_match_minimum_chain_size"], nlohmann::json({10, 14}));
  EXPECT_EQ(region["statement"].get<std::string>(), result.equivalent_region->Describe());
  // The history figure decodes: two panels per row, objectives then hypervolume.
  const cv::Mat history = cv::imread((dir / "history.png").string());
  ASSERT_FALSE(history.empty());
  EXPECT_GT(history.cols, 2 * 520);
  EXPECT_GT(history.rows, 2 * 420);

  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("How the search progressed"));
  EXPECT_THAT(html, HasSubstr("<a href=\"slices_corner_pixels.png\"><img"));
  EXPECT_THAT(html, HasSubstr("How sure: the parameter sets with an equivalent map"));
  EXPECT_THAT(html, HasSubstr("loop_search_maximum_distance in [2.6, 3.5], loop_match_minimum_chain_size in "
                              "[10, 14] give an equivalent map (4 of 12 evaluated parameter sets)."));
  // Under the recommendation, before the maps.
  EXPECT_LT(html.find("Why this recommendation"), html.find("How sure"));
  EXPECT_LT(html.find("How sure"), html.find("id=\"maps\""));
  // Every evaluation, in a sortable table collapsed in <details> (14 rows), failed runs named.
  EXPECT_THAT(html, HasSubstr("Every evaluation"));
  EXPECT_THAT(html, Not(HasSubstr("<details><summary>All 14 evaluations")));
  const std::size_t table = html.find("<table class=\"sortable\">");
  ASSERT_NE(table, std::string::npos);
  const std::string rows = html.substr(table, html.find("</table>", table) - table);
  EXPECT_EQ(Count(rows, "<tr>"), 1 + 14);
  EXPECT_THAT(rows, HasSubstr("<th title=\"click to sort\">loop_<wbr>search_<wbr>maximum_<wbr>distance</th>"));
  EXPECT_THAT(rows, HasSubstr("failed: scan matcher threw: bad, &quot;quoted&quot; reason"));
  // A long list is collapsed.
  optim::OptimizeResult many = result;
  for (int i = 0; i < 10; ++i) many.evaluations.push_back(result.evaluations[i]);
  const fs::path long_dir = FreshDir("history_long");
  WriteOptimizeReport(many, long_dir.string());
  EXPECT_THAT(ReadWholeFile(long_dir / "report.html"), HasSubstr("<details><summary>All 24 evaluations"));
  // Without generations or a region, neither section.
  optim::OptimizeResult bare = result;
  bare.history = {};
  bare.equivalent_region.reset();
  const fs::path bare_dir = FreshDir("history_bare");
  const auto summary = WriteOptimizeReport(bare, bare_dir.string());
  EXPECT_THAT(summary.files, Not(::testing::Contains(std::string("history.png"))));
  const std::string bare_html = ReadWholeFile(bare_dir / "report.html");
  EXPECT_THAT(bare_html, Not(HasSubstr("How the search progressed")));
  EXPECT_THAT(bare_html, Not(HasSubstr("How sure")));
  EXPECT_TRUE(nlohmann::json::parse(ReadWholeFile(bare_dir / "results.json"))["equivalent_region"].is_null());
}

TEST(WriteOptimizeReport, WithoutRelationsLeavesOutTheErrorOutputs) {
  const fs::path dir = FreshDir("nogt");
  const auto summary = WriteOptimizeReport(testing::FakeOptimizeResult(false), dir.string());
  EXPECT_FALSE(fs::exists(dir / "table9_10_errors.csv"));
  EXPECT_FALSE(fs::exists(dir / "objective_vs_error.png"));
  EXPECT_FALSE(summary.correlation.has_value());
  const auto j = nlohmann::json::parse(ReadWholeFile(dir / "results.json"));
  EXPECT_FALSE(j["recommended"].contains("gt_error"));
  EXPECT_TRUE(j["lowest_error"].is_null());
  EXPECT_FALSE(j.contains("error_correlation"));
  EXPECT_THAT(ReadWholeFile(dir / "report.html"), Not(HasSubstr("Spearman")));
}

TEST(WriteOptimizeReport, CandidatesNoteNamesTheSearchedParameters) {
  const fs::path loop = FreshDir("legend_loop");
  WriteOptimizeReport(testing::FakeOptimizeResult(false), loop.string());
  EXPECT_THAT(ReadWholeFile(loop / "report.html"),
              HasSubstr("Parameters: r = loop_search_maximum_distance (m), g = loop_match_minimum_chain_size."));
  // A space of other parameters: the note names only the symbols the table uses.
  optim::OptimizeResult other = testing::FakeOptimizeResult(false);
  other.space.dimensions[0].name = "correlation_search_space_dimension";
  const fs::path dir = FreshDir("legend_other");
  WriteOptimizeReport(other, dir.string());
  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("Parameters: g = loop_match_minimum_chain_size."));
  EXPECT_THAT(html, Not(HasSubstr("r = loop_search_maximum_distance")));
}

TEST(WriteOptimizeReport, ParameterSpaceCaptionSaysHowToReadItsView) {
  const fs::path two = FreshDir("space_two");
  WriteOptimizeReport(testing::FakeOptimizeResult(true), two.string());
  const std::string grid = ReadWholeFile(two / "report.html");
  EXPECT_THAT(grid, HasSubstr("drawn once per panel"));
  EXPECT_THAT(grid, HasSubstr("by the quarter of its true translational error"));
  EXPECT_THAT(grid, Not(HasSubstr("parallel coordinates")));
  optim::OptimizeResult three = testing::FakeOptimizeResult(false);
  three.space.dimensions.push_back({"loop_match_minimum_response_coarse", 0.5, 0.9, false});
  const fs::path dir = FreshDir("space_three");
  WriteOptimizeReport(three, dir.string());
  const std::string parallel = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(parallel, HasSubstr("in parallel coordinates"));
  EXPECT_THAT(parallel, HasSubstr("a last axis for eta"));
  EXPECT_THAT(parallel, Not(HasSubstr("drawn once per panel")));
  const cv::Mat figure = cv::imread((dir / "parameter_space.png").string());
  ASSERT_FALSE(figure.empty());
  EXPECT_GT(figure.cols, 3 * 520);
}

TEST(WriteOptimizeReport, TablesMirrorThePapers) {
  const fs::path dir = FreshDir("tables");
  WriteOptimizeReport(testing::FakeOptimizeResult(true), dir.string());
  const std::string t3 = ReadWholeFile(dir / "table3_best_worst_params.csv");
  EXPECT_EQ(t3.substr(0, t3.find('\n')), "label,loop_search_maximum_distance,loop_match_minimum_chain_size");
  EXPECT_THAT(t3, HasSubstr("\nrecommended,3,12\n"));
  EXPECT_THAT(t3, HasSubstr("\ndefault,4,10\n"));
  const std::string t4 = ReadWholeFile(dir / "table4_6_objectives.csv");
  EXPECT_EQ(t4.substr(0, t4.find('\n')),
            "label,eta,eta_known,corner_pixels,corners,enclosed_areas,contours,unbacked_hits");
  // Listed recommended, knee, default, worst.
  EXPECT_LT(t4.find("\nrecommended,"), t4.find("\nknee,"));
  EXPECT_LT(t4.find("\nknee,"), t4.find("\ndefault,"));
  EXPECT_LT(t4.find("\ndefault,"), t4.find("\nworst,"));
  EXPECT_THAT(ReadWholeFile(dir / "table7_loop_closures.csv"), HasSubstr("\nrecommended,11\n"));
  EXPECT_THAT(ReadWholeFile(dir / "table8_loop_scans.csv"), HasSubstr("\nworst,100 137 174 211\n"));
  EXPECT_THAT(ReadWholeFile(dir / "table9_10_errors.csv"), HasSubstr("\nknee,0.035,0.015,0.6,0.35,250\n"));
  const std::string ev = ReadWholeFile(dir / "evaluations.csv");
  EXPECT_EQ(std::count(ev.begin(), ev.end(), '\n'), 1 + 14);
  // The failed run's reason is quoted; its metric cells are empty.
  EXPECT_THAT(ev, HasSubstr("failed,\"scan matcher threw: bad, \"\"quoted\"\" reason\",,,,,,,,,"));
}

TEST(WriteOptimizeReport, HtmlIsSelfContainedEscapedAndStatesTheVerdict) {
  const fs::path dir = FreshDir("html");
  WriteOptimizeReport(testing::FakeOptimizeResult(true), dir.string());
  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("The recommendation &lt;r=3, g=12&gt; beats the defaults &amp; closes more loops."));
  EXPECT_THAT(html, Not(HasSubstr("<r=3")));
  // The first screen's two maps (base, recommended), four maps, three generations, evolution,
  // history, parameter space, three slices, objective vs error.
  EXPECT_EQ(Count(html, "src=\"data:image/png;base64,iVBORw0KGgo"), 16);
  // The verdict and both maps come first, before any section.
  EXPECT_LT(html.find("class=\"verdict\""), html.find("<h2"));
  EXPECT_LT(html.find("alt=\"the recommended map\""), html.find("<h2"));
  EXPECT_LT(html.find("alt=\"the base configuration, mapped\""), html.find("<h2"));
  // One inline script: the one that sorts the table of evaluations; nothing loaded from elsewhere.
  EXPECT_EQ(Count(html, "<script"), 1);
  EXPECT_THAT(html, Not(HasSubstr("<script src")));
  EXPECT_THAT(html, Not(HasSubstr("http://")));
  EXPECT_THAT(html, Not(HasSubstr("https://")));
  EXPECT_THAT(html, HasSubstr("intel.clf.gz"));
  EXPECT_THAT(html, HasSubstr("Spearman rho"));
  EXPECT_THAT(html, HasSubstr("barely rank working runs"));
  EXPECT_THAT(html, HasSubstr("100 137 174"));         // loop-closure scan indices
  EXPECT_THAT(html, HasSubstr("0.035 \u00b1 0.015"));  // knee's translational error
  EXPECT_THAT(html, HasSubstr("5 of 8 individuals"));
}

TEST(WriteOptimizeReport, HtmlReadsAtAGlance) {
  const fs::path dir = FreshDir("glance");
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  r.settings["tolerance"] = 0.40000000000000002;
  r.settings["engine"] = {{"base", {{"resolution", 0.05}, {"scan_buffer_size", 70}}}, {"log", "office"}};
  r.settings["default"] = {{"loop_search_maximum_distance", 4.0}};
  WriteOptimizeReport(r, dir.string());
  const std::string html = ReadWholeFile(dir / "report.html");
  // Settings as key/value rows: nested keys joined, no JSON and no float noise.
  EXPECT_THAT(html, HasSubstr("<th>tolerance</th><td>0.4</td>"));
  EXPECT_THAT(html, HasSubstr("<th>default.loop_search_maximum_distance</th><td>4</td>"));
  EXPECT_THAT(html, HasSubstr("<th>base.scan_buffer_size</th><td>70</td>"));  // engine settings, collapsed
  EXPECT_THAT(html, HasSubstr("<details><summary>Engine settings"));
  EXPECT_THAT(html, Not(HasSubstr("0.40000000000000002")));
  EXPECT_THAT(html, Not(HasSubstr("{&quot;")));
  // Maps two per row, each linking to its full-size file.
  EXPECT_THAT(html, HasSubstr("grid-template-columns:repeat(2,minmax(0,1fr))"));
  EXPECT_THAT(html, HasSubstr("<a href=\"map_recommended.png\"><img"));
  // The reasons for the choice: 5 of 8 share it (a majority), the knee is another set.
  EXPECT_THAT(html, HasSubstr("Why this recommendation"));
  EXPECT_THAT(html, HasSubstr("5 of 8 individuals of the final population hold the recommended set (r=3 g=12)"));
  EXPECT_THAT(html, HasSubstr("The knee of the final front is another set (r=3.5 g=10)"));
  EXPECT_THAT(html, Not(HasSubstr("class=\"warning\"")));  // r = 3 and g = 12 sit inside their ranges
}

TEST(WriteOptimizeReport, MergesTheSameSetAndWarnsOnABound) {
  const fs::path dir = FreshDir("merged");
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  r.candidates[0].record = testing::FakeRecord(6.0, 12, 0.1, false);  // r on the upper bound of [2, 6]
  r.candidates[1].record = r.candidates[0].record;                    // the knee is the same set
  r.recommended_share = 1;
  const auto summary = WriteOptimizeReport(r, dir.string());
  EXPECT_THAT(summary.files, ::testing::Contains(std::string("map_recommended_knee.png")));
  EXPECT_FALSE(fs::exists(dir / "map_knee.png"));
  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_EQ(Count(html, "alt=\"map of "), 3);
  EXPECT_THAT(html, HasSubstr("alt=\"map of recommended = knee\""));
  EXPECT_THAT(html, HasSubstr("falls back to the tie-break"));
  EXPECT_THAT(html, HasSubstr("It is also the knee of the final front"));
  EXPECT_THAT(html, HasSubstr("<p class=\"warning\">r = 6 sits on the upper bound of its search range [2, 6]"));
  EXPECT_THAT(html, HasSubstr("Widen the search range"));
}

TEST(WriteOptimizeReport, CallsAPluralityTentativeAndSaysWhatToDoNext) {
  const fs::path dir = FreshDir("plurality");
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  r.recommended_share = 3;  // of 8
  r.verdict_kind = optim::VerdictKind::kWorse;
  r.base_label = "your configuration (base.yaml)";
  WriteOptimizeReport(r, dir.string());
  const std::string html = ReadWholeFile(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("but only 3 of 8 hold it: the largest group, not a majority"));
  EXPECT_THAT(html, HasSubstr("<th>recommended share</th><td>3 of 8 individuals of the final population</td>"));
  EXPECT_THAT(html, HasSubstr("<li>Keep your configuration (base.yaml): the recommendation does not map this log"));
  EXPECT_THAT(html, HasSubstr("<li>Run again with more generations (--generations)"));
  EXPECT_THAT(html, HasSubstr("<li>With ground truth for this log (--relations FILE)"));
  EXPECT_THAT(html, Not(HasSubstr("Widen the search range")));
}

TEST(WriteOptimizeReport, IsDeterministic) {
  const fs::path a = FreshDir("det_a"), b = FreshDir("det_b");
  WriteOptimizeReport(testing::FakeOptimizeResult(true), a.string());
  WriteOptimizeReport(testing::FakeOptimizeResult(true), b.string());
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    EXPECT_EQ(ReadWholeFile(entry.path()), ReadWholeFile(b / entry.path().filename())) << entry.path().filename();
    ++compared;
  }
  EXPECT_EQ(compared, 29);
}

TEST(WriteOptimizeReport, DegenerateResultStillWritesAReport) {
  optim::OptimizeResult empty;
  empty.source.log_label = "x.clf";
  const fs::path dir = FreshDir("empty");
  const auto summary = WriteOptimizeReport(empty, dir.string());
  EXPECT_TRUE(fs::exists(dir / "report.html"));
  EXPECT_TRUE(fs::exists(dir / "results.json"));
  EXPECT_FALSE(fs::exists(dir / "maps_side_by_side.png"));
  const auto j = nlohmann::json::parse(ReadWholeFile(dir / "results.json"));
  EXPECT_TRUE(j["recommended"].is_null());
  // A population made only of failed individuals, and a single candidate without a map.
  optim::OptimizeResult failed = testing::FakeOptimizeResult(false);
  failed.candidates.resize(1);
  failed.candidates[0].map = io::MapImage{};
  failed.snapshots.resize(1);
  failed.snapshots[0].objectives.assign(3, {1.0, 1e9, 1e9});
  EXPECT_NO_THROW(WriteOptimizeReport(failed, FreshDir("failed").string()));
}

TEST(WriteOptimizeReport, UnwritableFolderIsAnInputError) {
  const fs::path file = FreshDir("file_in_the_way") / "a_file";
  std::ofstream(file.string()) << "x";
  try {
    WriteOptimizeReport(testing::FakeOptimizeResult(false), file.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
  }
}

}  // namespace
}  // namespace slamtune::report
