// A rendered image (renderer/image/image.h) and writing it (image_output.h): what the file holds.
#include "renderer/image/image_output.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace pdrt;

// sized_image sizes every plane, all zero (write_image_pixel then fills each pixel, and the AOV
// planes a pixel has no value for stay 0); its tasks zero one group of planes each.
TEST(Image, SizedImageHasEveryPlaneSizedAndZero) {
  const Image img = sized_image(37, 23);
  const std::size_t n = 37 * 23;
  EXPECT_EQ(img.width, 37);
  EXPECT_EQ(img.height, 23);
  const std::pair<const std::vector<float>*, std::size_t> planes[] = {{&img.rgb, 3 * n},    {&img.albedo, 3 * n},
                                                                      {&img.normal, 3 * n}, {&img.samples, n},
                                                                      {&img.variance, n},   {&img.depth, n}};
  for (const auto& [p, size] : planes) {
    ASSERT_EQ(p->size(), size);
    for (float v : *p) ASSERT_EQ(v, 0.0f);
  }
}

// The EXR's twelve channels, pixel by pixel, are the image's planes: the pixels are interleaved
// in parallel chunks of 4,096, so an image of 5,917 pixels (a chunk and a partial one) checks
// each chunk's pixels land in their own places, channel by channel.
TEST(ImageOutput, EveryExrChannelHoldsItsPlanesValueAtEveryPixel) {
  const int w = 97, h = 61;
  const std::size_t n = std::size_t(w) * h;
  Image img;
  img.width = w, img.height = h;
  // Channel c of pixel i holds i + c / 16 (exact in float for these sizes).
  const auto value = [](std::size_t i, int c) { return float(i) + float(c) / 16; };
  const auto plane = [&](int first, int comps) {
    std::vector<float> p(n * comps);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < comps; ++k) p[i * comps + k] = value(i, first + k);
    return p;
  };
  img.rgb = plane(0, 3), img.samples = plane(3, 1), img.variance = plane(4, 1);
  img.albedo = plane(5, 3), img.normal = plane(8, 3), img.depth = plane(11, 1);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("pdrt_image_output_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "planes.exr";
  write_image(path, img, {});

  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 12);
  const std::vector<std::string> names = {"R",        "G",        "B",   "samples", "variance", "albedo.R",
                                          "albedo.G", "albedo.B", "N.X", "N.Y",     "N.Z",      "Z"};
  std::vector<float> got(n * 12);
  ASSERT_TRUE(in->read_image(0, 0, 0, 12, OIIO::TypeDesc::FLOAT, got.data()));
  for (int c = 0; c < 12; ++c) {
    // The file's channel order is the writer's choice: find each by name.
    const auto& file_names = in->spec().channelnames;
    const auto at = std::find(file_names.begin(), file_names.end(), names[std::size_t(c)]);
    ASSERT_NE(at, file_names.end()) << names[std::size_t(c)];
    const std::size_t fc = std::size_t(at - file_names.begin());
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(got[i * 12 + fc], value(i, c)) << names[std::size_t(c)] << " at pixel " << i;
  }
  in.reset();
  std::filesystem::remove_all(dir);
}
