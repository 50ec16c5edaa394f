// map_server YAML (io/map_image.h ReadMap): the input is the YAML; beside it lie a valid
// map.pgm and map.png (4 x 3 pixels) that it may name, so that the keys after `image` are
// reached.
#include <cstdint>
#include <vector>

#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/image_codec.h"
#include "slamtune/io/map_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool images_written = [] {
    const std::vector<std::uint8_t> pixels = {0, 254, 205, 100, 254, 254, 0, 0, 205, 205, 30, 250};
    slamtune::fuzz::WriteTempFile("map.pgm", slamtune::io::EncodePgm(4, 3, pixels.data()));
    slamtune::fuzz::WriteTempFile("map.png", slamtune::io::EncodeGreyPng(4, 3, pixels.data()));
    return true;
  }();
  (void)images_written;
  const std::string path = slamtune::fuzz::WriteTempFile("map.yaml", slamtune::fuzz::AsText(data, size));
  try {
    slamtune::io::ReadMap(path);
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
