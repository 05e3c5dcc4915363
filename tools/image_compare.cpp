// Relative mean squared error of images against a reference (all PFM, linear
// radiance): mean over pixels and channels of (x - r)^2 / (r^2 + 0.01), the
// measure of the papers. Usage: image_compare REFERENCE.pfm IMAGE.pfm [IMAGE.pfm ...]
#include <cstdio>
#include <exception>

#include "engine/image/image_io.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s REFERENCE.pfm IMAGE.pfm [IMAGE.pfm ...]\n", argv[0]);
    return 2;
  }
  try {
    qlight::image::LinearImage ref = qlight::image::readPfm(argv[1]);
    for (int i = 2; i < argc; ++i) {
      qlight::image::LinearImage img = qlight::image::readPfm(argv[i]);
      if (img.width != ref.width || img.height != ref.height) {
        std::fprintf(stderr, "image_compare: %s is %ux%u, the reference %ux%u\n", argv[i],
                     img.width, img.height, ref.width, ref.height);
        return 1;
      }
      double sum = 0;
      size_t n = 0;
      for (size_t p = 0; p < size_t(ref.width) * ref.height; ++p)
        for (int c = 0; c < 3; ++c) {
          double r = ref.rgba[p * 4 + c], x = img.rgba[p * 4 + c];
          sum += (x - r) * (x - r) / (r * r + 0.01);
          ++n;
        }
      std::printf("%s relMSE %.6g\n", argv[i], sum / double(n));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "image_compare: %s\n", e.what());
    return 1;
  }
  return 0;
}
