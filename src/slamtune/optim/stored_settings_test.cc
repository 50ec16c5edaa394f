#include "slamtune/optim/stored_settings.h"

#include <gtest/gtest.h>

#include "slamtune/optim/settling.h"

namespace slamtune::optim {
namespace {

TEST(UpgradeStoredSettings, OldFoldersReadAsTheyRanAndNewKeysTakeTodaysValues) {
  const nlohmann::json current = {{"seed", 1},
                                  {"objectives", "occupied"},
                                  {"settling", SettlingOptions{}.ToJson()},
                                  {"engine", {{"base", {{"a", 1}, {"new_parameter", 2}}}, {"inputs", {{"x", 1}}}}}};
  const nlohmann::json oldest = {{"seed", 1}, {"engine", {{"base", {{"a", 1}}}}}};
  const nlohmann::json upgraded = UpgradeStoredSettings(oldest, current);
  EXPECT_EQ(upgraded.at("objectives"), "paper");
  EXPECT_EQ(upgraded.at("settling"), SettlingOptions{false}.ToJson());
  EXPECT_EQ(upgraded.at("engine").at("base").at("new_parameter"), 2);
  EXPECT_EQ(upgraded.at("engine").at("inputs"), current.at("engine").at("inputs"));
  // What a folder recorded is kept, even where today's value differs.
  nlohmann::json recorded = current;
  recorded["engine"]["base"]["a"] = 5;
  EXPECT_EQ(UpgradeStoredSettings(recorded, current).at("engine").at("base").at("a"), 5);
  EXPECT_EQ(UpgradeStoredSettings(current, current), current);
}

}  // namespace
}  // namespace slamtune::optim
