#include "slamtune/io/scan_losses.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace slamtune::io {
namespace {

LaserLog RecordingLog() {
  LaserLog log;
  log.path = "drive.bag";
  log.recording.emplace();
  return log;
}

// A sound log loses nothing: every reading kind is there with a count of 0, and no line.
TEST(ScanLosses, ASoundLogHasEveryReadingKindAtZero) {
  const ScanLosses losses = ReadingLosses(RecordingLog());
  ASSERT_EQ(losses.kinds.size(), 4u);
  for (const ScanLoss& k : losses.kinds) EXPECT_EQ(k.count, 0u) << NameOf(k.kind);
  EXPECT_EQ(losses.kinds[0].kind, ScanLossKind::kNoOdometry);
  EXPECT_EQ(losses.kinds[3].kind, ScanLossKind::kWrongReadingCount);
  EXPECT_TRUE(losses.LossLines().empty());
  EXPECT_EQ(losses.counted(), 0u);
}

// Each kind with its count, its first occurrence and why, in one line each.
TEST(ScanLosses, EachReadingKindSaysHowManyAndTheFirst) {
  LaserLog log = RecordingLog();
  RecordingInfo& r = *log.recording;
  r.scans_unplaced = 11;
  r.unplaced_examples = {"scan 40 at 104.025000 s: odom -> base_link at 104.025000 s: no sample for 1.100 s"};
  r.tf_bad_rotations = 21;
  r.scans_malformed = 2;
  r.malformed_examples = {"drive.bag: byte 9000: /scan: LaserScan has 6 ranges but its angles give 5 beams"};
  r.data_end.dropped_bytes = 5785;
  r.data_end.dropped_reason = "drive.bag: byte 94215 (Chunk record): content length 42853 runs past the end";
  r.data_end.complete = false;
  r.data_end.how =
      "cut off inside a record: read up to its last whole record, the last 5785 bytes (5.8 % of the file) "
      "not read (" +
      r.data_end.dropped_reason + ")";
  log.beams.slam_karto = {181, 7};
  log.beams.slam_toolbox = {181, 5};
  log.beams.policy = "node";
  const ScanLosses losses = ReadingLosses(log, KartoLaserRule::kSlamToolbox);
  EXPECT_EQ(losses.Find(ScanLossKind::kNoOdometry)->count, 11u);
  EXPECT_EQ(losses.Find(ScanLossKind::kMalformed)->count, 2u);
  EXPECT_FALSE(losses.Find(ScanLossKind::kCutOff)->count.has_value());
  EXPECT_EQ(losses.Find(ScanLossKind::kCutOff)->bytes, 5785u);
  EXPECT_EQ(losses.Find(ScanLossKind::kWrongReadingCount)->count, 5u);  // slam_toolbox's
  EXPECT_EQ(losses.Find(ScanLossKind::kWrongReadingCount)->by.at("slam_karto"), 7u);
  EXPECT_EQ(losses.counted(), 18u);
  EXPECT_THAT(
      losses.LossLines(),
      ::testing::ElementsAre(
          "not used: 11 scans without odometry at their stamp (21 tf transforms refused: NaN, inf or a bad "
          "rotation, or a bad frame id) (first: scan 40 at 104.025000 s: odom -> base_link at 104.025000 s: "
          "no sample for 1.100 s)",
          "not used: 2 malformed scans, skipped (--lenient) (first: drive.bag: byte 9000: /scan: LaserScan "
          "has 6 ranges but its angles give 5 beams)",
          "not used: the scans in the last 5785 bytes of the recording (how many is not known): cut off inside a "
          "record: read up to its last whole record, the last 5785 bytes (5.8 % of the file) not read "
          "(drive.bag: byte 94215 (Chunk record): content length 42853 runs past the end)",
          "not used: 5 scans whose reading count differs from what slam_toolbox's Karto laser expects: the "
          "node drops them (make the driver publish a fixed count)"));
  // Without a node: the larger count; with --beams per-geometry the engine keeps them.
  EXPECT_EQ(ReadingLosses(log).Find(ScanLossKind::kWrongReadingCount)->count, 7u);
  log.beams.policy = "per-geometry";
  EXPECT_EQ(ReadingLosses(log).Find(ScanLossKind::kWrongReadingCount)->count, 0u);
}

// A recording without its end marker: the count is not known, and the line says so.
TEST(ScanLosses, ARecordingWithoutItsEndMarkerMayHaveLostItsEnd) {
  LaserLog log = RecordingLog();
  log.recording->data_end.complete = false;
  log.recording->data_end.how = "no data end record: the file ends after a complete record (recording cut off?)";
  const ScanLosses losses = ReadingLosses(log);
  EXPECT_TRUE(losses.Find(ScanLossKind::kCutOff)->happened());
  EXPECT_THAT(losses.LossLines(), ::testing::ElementsAre(::testing::HasSubstr("it ends without its end marker")));
}

// CARMEN logs: RAWLASER scans outside the ODOM records and malformed laser records (--lenient).
TEST(ScanLosses, CarmenScansWithoutOdometryOrMalformed) {
  LaserLog log;
  log.scans_without_odometry = 3;
  log.first_scan_without_odometry = "line 12 at 130.5 s; ODOM 100 .. 120 s";
  log.skipped_records = 4;
  log.skipped_scans = 2;
  log.first_skipped_scan = "line 7: FLASER: expected 180 readings";
  const ScanLosses losses = ReadingLosses(log);
  EXPECT_EQ(losses.Find(ScanLossKind::kNoOdometry)->count, 3u);
  EXPECT_EQ(losses.Find(ScanLossKind::kMalformed)->count, 2u);
  EXPECT_THAT(losses.LossLines()[1], ::testing::HasSubstr("2 malformed laser records, skipped (--lenient) (first: "
                                                          "line 7"));
}

TEST(ScanLosses, NamesAndWhetherEachKindIsDataLoss) {
  EXPECT_STREQ(NameOf(ScanLossKind::kFilteredByNode), "filtered_by_node");
  EXPECT_TRUE(IsDataLoss(ScanLossKind::kCutOff));
  EXPECT_FALSE(IsDataLoss(ScanLossKind::kNotMoved));
  EXPECT_FALSE(IsDataLoss(ScanLossKind::kFilteredByNode));
  ScanLosses losses;
  losses.Get(ScanLossKind::kNotMoved).count = 4;
  losses.Get(ScanLossKind::kNoOdometry).count = 1;
  EXPECT_EQ(losses.kinds.front().kind, ScanLossKind::kNoOdometry);  // kept in kind order
  EXPECT_EQ(losses.LossLines().size(), 1u);                         // not_moved is no loss
}

}  // namespace
}  // namespace slamtune::io
