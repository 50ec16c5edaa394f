// Mapper parameter YAML, slam_toolbox ROS 2 files and flat slam_karto files (slam/params/params_yaml.h).
#include <string>

#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/params/params_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  slamtune::slam::MapperParams params;
  try {
    slamtune::slam::ApplyParamsYaml(params, std::string(slamtune::fuzz::AsText(data, size)), "fuzz.yaml");
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
