// `candela-golden compare` and `candela-golden inspect`: the comparison on any two files.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "diff_image.h"
#include "golden_commands.h"
#include "golden_comparison.h"

namespace candela::golden {

namespace {

namespace fs = std::filesystem;

bool hasExtension(const fs::path& path, const char* extension) {
    std::string actual = path.extension().string();
    std::transform(actual.begin(), actual.end(), actual.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return actual == extension;
}

int reportVerdict(const std::vector<std::string>& failures, const std::string& metrics,
                  std::ostream& out) {
    out << (failures.empty() ? "PASS" : "FAIL") << "\n  " << metrics << "\n";
    for (const std::string& failure : failures)
        out << "  FAIL: " << failure << "\n";
    return failures.empty() ? kExitPass : kExitDiffers;
}

bool writeDiff(const std::optional<fs::path>& path, const LdrImage& diff, std::ostream& out) {
    if (!path) return true;
    if (std::string error = writeLdrPng(*path, diff); !error.empty()) {
        out << error << "\n";
        return false;
    }
    out << "  diff: " << fs::absolute(*path).string() << "\n";
    return true;
}

double luminanceOf(const HdrImage& image, std::size_t pixel) {
    return 0.2126 * image.rgb[pixel * 3] + 0.7152 * image.rgb[pixel * 3 + 1] +
           0.0722 * image.rgb[pixel * 3 + 2];
}

// The image's mean relative luminance error, sum |Y_a - Y_e| / sum Y_e: what the frame
// benchmark reports of each quality preset against ultra (docs/frame-budget.md).
double meanRelativeLuminanceError(const HdrImage& actual, const HdrImage& expected) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < expected.pixelCount(); ++i) {
        const double y = luminanceOf(expected, i);
        difference += std::abs(luminanceOf(actual, i) - y);
        total += std::abs(y);
    }
    return total > 0.0 ? difference / total : (difference > 0.0 ? 1.0 : 0.0);
}

int compareExr(const fs::path& actualPath, const fs::path& expectedPath,
               const std::optional<fs::path>& diffPng, const HdrThresholds& thresholds,
               std::ostream& out) {
    std::string error;
    std::optional<LoadedHdr> actual = readHdrExr(actualPath, error);
    std::optional<LoadedHdr> expected = actual ? readHdrExr(expectedPath, error) : std::nullopt;
    if (!actual || !expected) {
        out << error << "\n";
        return kExitUnusable;
    }
    HdrComparison comparison = compareHdrImages(*actual, *expected, thresholds);
    int verdict = reportVerdict(comparison.failures, describe(comparison, thresholds), out);
    if (comparison.sameSize) {
        out << "  mean relative luminance error "
            << meanRelativeLuminanceError(actual->image, expected->image) << "\n";
        LdrImage diff = falseColourDiff(comparison.difference.errorInTolerances,
                                        backdropFromHdr(expected->image), expected->image.width,
                                        expected->image.height, thresholds.hardLimitInTolerances);
        if (!writeDiff(diffPng, diff, out)) return kExitUnusable;
    }
    return verdict;
}

int comparePng(const fs::path& actualPath, const fs::path& expectedPath,
               const std::optional<fs::path>& diffPng, const LdrThresholds& thresholds,
               std::ostream& out) {
    std::string error;
    std::optional<LdrImage> actual = readLdrPng(actualPath, error);
    std::optional<LdrImage> expected = actual ? readLdrPng(expectedPath, error) : std::nullopt;
    if (!actual || !expected) {
        out << error << "\n";
        return kExitUnusable;
    }
    LdrComparison comparison = compareLdrImages(*actual, *expected, thresholds);
    int verdict = reportVerdict(comparison.failures, describe(comparison, thresholds), out);
    if (comparison.sameSize) {
        LdrImage diff =
            falseColourDiff(comparison.difference.errorInTolerances, backdropFromLdr(*expected),
                            expected->width, expected->height, thresholds.hardLimitInTolerances());
        if (!writeDiff(diffPng, diff, out)) return kExitUnusable;
    }
    return verdict;
}

}  // namespace

int compareImageFiles(const fs::path& actual, const fs::path& expected,
                      const std::optional<fs::path>& diffPng, const GoldenThresholds& thresholds,
                      std::ostream& out) {
    if (hasExtension(actual, ".exr") && hasExtension(expected, ".exr")) {
        return compareExr(actual, expected, diffPng, thresholds.hdr, out);
    }
    if (hasExtension(actual, ".png") && hasExtension(expected, ".png")) {
        return comparePng(actual, expected, diffPng, thresholds.ldr, out);
    }
    out << "compare needs two .exr or two .png files, got " << actual.string() << " and "
        << expected.string() << "\n";
    return kExitUnusable;
}

int inspectExr(const fs::path& path, std::ostream& out) {
    std::string error;
    std::optional<LoadedHdr> loaded = readHdrExr(path, error);
    if (!loaded) {
        out << error << "\n";
        return kExitUnusable;
    }
    const HdrImage& image = loaded->image;
    double minLuminance = std::numeric_limits<double>::infinity(), maxLuminance = 0, sum = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const double y = luminanceOf(image, i);
        minLuminance = std::min(minLuminance, y);
        maxLuminance = std::max(maxLuminance, y);
        sum += y;
    }
    out << path.string() << ": " << image.width << "x" << image.height << ", luminance min "
        << minLuminance << " mean " << sum / double(std::max<std::size_t>(image.pixelCount(), 1))
        << " max " << maxLuminance << " cd/m^2, NaN/Inf texels " << loaded->nonFiniteTexels << "\n";
    if (image.pixelCount() == 0) return kExitUnusable;
    return loaded->nonFiniteTexels == 0 ? kExitPass : kExitDiffers;
}

}  // namespace candela::golden
