#include <algorithm>
#include <ostream>
#include <system_error>
#include <utility>
#include <vector>

#include "diff_image.h"
#include "golden_commands.h"
#include "golden_comparison.h"

namespace candela::golden {

namespace {

namespace fs = std::filesystem;

fs::path absolutePath(const fs::path& path) {
    std::error_code ec;
    fs::path result = fs::absolute(path, ec);
    return ec ? path : result.lexically_normal();
}

struct GoldenFiles {
    fs::path actualExr, actualPng, expectedExr, expectedPng;
    fs::path copiedExpectedExr, copiedExpectedPng, diffHdr, diffPng;
};

GoldenFiles goldenFiles(const CheckRequest& request) {
    const fs::path out = request.outputDir.empty() ? request.actualDir : request.outputDir;
    const std::string& n = request.name;
    return {absolutePath(request.actualDir / (n + ".exr")),
            absolutePath(request.actualDir / (n + ".png")),
            absolutePath(request.expectedDir / (n + ".exr")),
            absolutePath(request.expectedDir / (n + ".png")),
            absolutePath(out / (n + ".expected.exr")),
            absolutePath(out / (n + ".expected.png")),
            absolutePath(out / (n + ".diff-hdr.png")),
            absolutePath(out / (n + ".diff-png.png"))};
}

// Images of an earlier failure would otherwise survive a later pass and mislead.
void removeFailureImages(const GoldenFiles& files) {
    std::error_code ec;
    for (const fs::path& path :
         {files.copiedExpectedExr, files.copiedExpectedPng, files.diffHdr, files.diffPng}) {
        fs::remove(path, ec);
    }
}

bool reportMissing(const CheckRequest& request, const GoldenFiles& files, std::ostream& out) {
    std::vector<fs::path> missing;
    for (const fs::path& path : {files.expectedExr, files.expectedPng}) {
        if (!fs::exists(path)) missing.push_back(path);
    }
    if (missing.empty()) return false;
    out << "golden " << request.name << ": FAIL: no expected image";
    for (const fs::path& path : missing)
        out << " " << path.string();
    out << "\n  the new capture is " << files.actualExr.string() << " and "
        << files.actualPng.string() << "\n  if it is right, store it with: scripts/update-goldens "
        << request.name << " (and say in the commit message what it shows and why it is right)\n";
    return true;
}

// Writes what a person needs to see the failure, and says where it is.
void writeFailureImages(const GoldenFiles& files, const LoadedHdr& expectedHdr,
                        const LdrImage& expectedLdr, const HdrComparison& hdr,
                        const LdrComparison& ldr, const GoldenThresholds& thresholds,
                        std::ostream& out) {
    std::error_code ec;
    for (auto [from, to] : {std::pair{files.expectedExr, files.copiedExpectedExr},
                            std::pair{files.expectedPng, files.copiedExpectedPng}}) {
        if (from == to) continue;
        if (!fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec)) {
            out << "  cannot copy " << from.string() << " to " << to.string() << ": "
                << ec.message() << "\n";
        }
    }
    const bool backdropFromPng = expectedLdr.width == expectedHdr.image.width &&
                                 expectedLdr.height == expectedHdr.image.height;
    if (hdr.sameSize) {
        LdrImage diff = falseColourDiff(
            hdr.difference.errorInTolerances,
            backdropFromPng ? backdropFromLdr(expectedLdr) : backdropFromHdr(expectedHdr.image),
            hdr.difference.width, hdr.difference.height, thresholds.hdr.hardLimitInTolerances);
        if (std::string error = writeLdrPng(files.diffHdr, diff); !error.empty()) {
            out << "  " << error << "\n";
        }
    }
    if (ldr.sameSize) {
        LdrImage diff = falseColourDiff(
            ldr.difference.errorInTolerances, backdropFromLdr(expectedLdr), ldr.difference.width,
            ldr.difference.height, thresholds.ldr.hardLimitInTolerances());
        if (std::string error = writeLdrPng(files.diffPng, diff); !error.empty()) {
            out << "  " << error << "\n";
        }
    }
    out << "  actual:    " << files.actualExr.string() << "\n"
        << "             " << files.actualPng.string() << "\n"
        << "  expected:  " << files.copiedExpectedExr.string() << "\n"
        << "             " << files.copiedExpectedPng.string() << "\n";
    if (hdr.sameSize) out << "  HDR diff:  " << files.diffHdr.string() << "\n";
    if (ldr.sameSize) out << "  PNG diff:  " << files.diffPng.string() << "\n";
    out << "  diff colours: grey identical, blue within tolerance, yellow to orange over "
           "tolerance, red over the hard limit\n";
}

}  // namespace

int checkGolden(const CheckRequest& request, std::ostream& out) {
    const GoldenFiles files = goldenFiles(request);
    removeFailureImages(files);
    for (const fs::path& path : {files.actualExr, files.actualPng}) {
        if (!fs::exists(path)) {
            out << "golden " << request.name << ": the capture " << path.string()
                << " does not exist (did the render fail?)\n";
            return kExitUnusable;
        }
    }
    if (reportMissing(request, files, out)) return kExitDiffers;

    std::string error;
    std::optional<LoadedHdr> actualHdr, expectedHdr;
    std::optional<LdrImage> actualLdr, expectedLdr;
    if (!(actualHdr = readHdrExr(files.actualExr, error)) ||
        !(expectedHdr = readHdrExr(files.expectedExr, error)) ||
        !(actualLdr = readLdrPng(files.actualPng, error)) ||
        !(expectedLdr = readLdrPng(files.expectedPng, error))) {
        out << "golden " << request.name << ": " << error << "\n";
        return kExitUnusable;
    }

    const HdrComparison hdr = compareHdrImages(*actualHdr, *expectedHdr, request.thresholds.hdr);
    const LdrComparison ldr = compareLdrImages(*actualLdr, *expectedLdr, request.thresholds.ldr);
    const bool passed = hdr.passed() && ldr.passed();
    out << "golden " << request.name << ": " << (passed ? "PASS" : "FAIL") << "\n  "
        << describe(hdr, request.thresholds.hdr) << "\n  " << describe(ldr, request.thresholds.ldr)
        << "\n";
    if (passed) return kExitPass;
    for (const std::string& failure : hdr.failures)
        out << "  FAIL (HDR): " << failure << "\n";
    for (const std::string& failure : ldr.failures)
        out << "  FAIL (PNG): " << failure << "\n";
    writeFailureImages(files, *expectedHdr, *expectedLdr, hdr, ldr, request.thresholds, out);
    return kExitDiffers;
}

}  // namespace candela::golden
