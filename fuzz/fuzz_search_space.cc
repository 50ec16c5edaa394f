// Search-space YAML (optim/search_space.h SearchSpace::FromYaml), read from a file.
#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/optim/search_space.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = slamtune::fuzz::WriteTempFile("space.yaml", slamtune::fuzz::AsText(data, size));
  try {
    const auto space = slamtune::optim::SearchSpace::FromYaml(path);
    (void)space.Fingerprint();
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
