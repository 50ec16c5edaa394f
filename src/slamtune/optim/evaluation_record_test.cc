#include "slamtune/optim/evaluation_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(RunStatus, NamesAreOkAndFailedAndParseBack) {
  EXPECT_STREQ(NameOf(RunStatus::kOk), "ok");
  EXPECT_STREQ(NameOf(RunStatus::kFailed), "failed");
  EXPECT_EQ(ParseRunStatus("ok"), RunStatus::kOk);
  EXPECT_EQ(ParseRunStatus("failed"), RunStatus::kFailed);
}

TEST(RunStatus, OtherTextIsAnInputError) {
  EXPECT_THAT([] { ParseRunStatus("passed"); },
              ThrowsMessage<InputError>(HasSubstr("unknown evaluation status 'passed' (known: ok, failed)")));
  EXPECT_THROW(ParseRunStatus("OK"), InputError);
  EXPECT_THROW(ParseRunStatus(""), InputError);
}

TEST(EvaluationRecord, JsonHoldsTheStatusAsText) {
  EvaluationRecord ok;
  ok.key = "k";
  const nlohmann::json written = ok;
  EXPECT_EQ(written.at("status"), "ok");
  EXPECT_EQ(written.get<EvaluationRecord>().status, RunStatus::kOk);
  const EvaluationRecord failed = EvaluationRecord::Failed("k", {{"x", 1.0}}, "solver diverged");
  const nlohmann::json failed_json = failed;
  EXPECT_EQ(failed_json.at("status"), "failed");
  const EvaluationRecord back = failed_json.get<EvaluationRecord>();
  EXPECT_EQ(back.status, RunStatus::kFailed);
  EXPECT_EQ(back.reason, "solver diverged");
}

TEST(EvaluationRecord, AnUnknownStatusInJsonIsAnInputError) {
  nlohmann::json j = EvaluationRecord{};
  j["status"] = "done";
  EXPECT_THAT([&] { static_cast<void>(j.get<EvaluationRecord>()); },
              ThrowsMessage<InputError>(HasSubstr("unknown evaluation status 'done'")));
}

}  // namespace
}  // namespace slamtune::optim
