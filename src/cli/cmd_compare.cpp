/// `lucent compare A B`: error metrics of image A against the reference B, as text or JSON.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <lucent/image/metrics.hpp>

#include "../util/error.hpp"
#include "commands.hpp"
#include "image_output.hpp"
#include "json_writer.hpp"

namespace lucent::cli {

int runCompare(int argc, char** argv) {
  std::vector<OptionSpec> specs = toneMapOptionSpecs();
  specs.push_back({"json", "", "print the metrics as JSON"});
  Args args("compare", "lucent compare TEST.exr|png REFERENCE.exr|png [--json]", specs);
  args.parse(argc, argv, 2);
  if (args.helpRequested()) {
    std::cout << args.helpText()
              << "\nmetrics (DESIGN.md): rmse_tonemapped = RMSE of tone-mapped values in [0,1] "
                 "over all pixels, both\n"
                 "images mapped with the reference's L_avg; relative_rms = "
                 "sqrt(sum|a-b|^2/sum|b|^2) of linear\n"
                 "radiance over covered pixels; scaled_relative_rms = the same after each "
                 "channel of TEST is\nscaled by its least-squares factor (the error no "
                 "normalisation removes); max_abs_error = largest per-channel |a-b|. PNG "
                 "inputs are display\n"
                 "values already: only rmse (of those values) and max_abs_error are meaningful.\n";
    return 0;
  }
  if (args.positional().size() != 2) args.fail("needs exactly two images: TEST REFERENCE");
  const std::string testPath = args.positional()[0], refPath = args.positional()[1];
  const image::Image test = readImage(testPath), ref = readImage(refPath);
  const image::ToneMap tone = toneMapFromArgs(args);
  const bool linear = isExr(testPath) && isExr(refPath);
  if (!linear && isExr(testPath) != isExr(refPath))
    args.fail(
        "compare two EXR images (linear) or two PNG images (display values), not one of each");
  // An error measure against a reference that is broken or black means nothing: say so instead of
  // 0.
  auto requireFinite = [&](const image::Image& img, const std::string& path) {
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(img.pixels[i][c]))
          args.fail("'" + path + "' has a non-finite value at pixel (" +
                    std::to_string(i % std::size_t(img.width)) + ", " +
                    std::to_string(i / std::size_t(img.width)) + "); it cannot be compared");
  };
  requireFinite(test, testPath);
  requireFinite(ref, refPath);
  auto energy = [](const image::Image& img) {
    double sum = 0;
    for (const auto& p : img.pixels)
      sum += double(p.r) * p.r + double(p.g) * p.g + double(p.b) * p.b;
    return sum;
  };
  if (linear && !(energy(ref) > 0) && energy(test) > 0)  // the relative error divides by it
    args.fail("the reference '" + refPath +
              "' is black everywhere; an error relative to it is undefined "
              "(check how it was rendered)");
  image::ImageErrors e;
  try {
    e = linear ? image::compareImages(test, ref, tone) : image::compareDisplayImages(test, ref);
  } catch (const std::invalid_argument& ex) {
    throw InputError("lucent compare: '" + testPath + "' vs '" + refPath + "': " + ex.what());
  }
  if (args.has("json")) {
    JsonObject j;
    j.add("test", testPath).add("reference", refPath).add("rmse_tonemapped", e.rmseToneMapped);
    if (linear)
      j.add("relative_rms", e.relativeRms).add("scaled_relative_rms", e.scaledRelativeRms);
    j.add("max_abs_error", e.maxAbsError).add("covered_pixels", double(e.coveredPixels));
    if (linear) {
      j.add("coverage_mismatch", double(e.coverageMismatch));
      j.add("mean_ratio_r", e.meanRatio[0])
          .add("mean_ratio_g", e.meanRatio[1])
          .add("mean_ratio_b", e.meanRatio[2]);
    }
    std::printf("%s\n", j.str().c_str());
  } else {
    std::printf("rmse_tonemapped   %.6g\n", e.rmseToneMapped);
    if (linear) std::printf("relative_rms      %.6g\n", e.relativeRms);
    if (linear)
      std::printf("scaled_rel_rms    %.6g (after each channel's least-squares scale)\n",
                  e.scaledRelativeRms);
    std::printf("max_abs_error     %.6g\n", e.maxAbsError);
    if (linear) {
      std::printf("coverage_mismatch %zu of %zu covered pixels\n", e.coverageMismatch,
                  e.coveredPixels);
      std::printf(
          "mean_ratio        %.4g %.4g %.4g (R G B: test / reference, summed over covered "
          "pixels)\n",
          e.meanRatio[0], e.meanRatio[1], e.meanRatio[2]);
    }
  }
  return 0;
}

}  // namespace lucent::cli
