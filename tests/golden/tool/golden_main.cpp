// candela-golden: compares frame captures with stored goldens (see README.md "Golden tests").
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "golden_commands.h"

namespace {

using namespace candela::golden;

constexpr const char* kUsage =
    "usage: candela-golden check <name> --actual-dir DIR --expected-dir DIR [--output-dir DIR]\n"
    "       candela-golden compare ACTUAL.exr EXPECTED.exr [--diff DIFF.png]\n"
    "       candela-golden compare ACTUAL.png EXPECTED.png [--diff DIFF.png]\n"
    "       candela-golden inspect IMAGE.exr\n"
    "exit: 0 pass, 1 the images differ or a golden is missing, 2 bad arguments or files\n";

int usage(const std::string& problem) {
    std::cerr << "candela-golden: " << problem << "\n" << kUsage;
    return kExitUnusable;
}

// Splits "--flag value" pairs from positional arguments; nullopt on an unknown flag.
struct Arguments {
    std::vector<std::string> positional;
    std::vector<std::pair<std::string, std::string>> flags;

    std::optional<std::string> flag(const std::string& name) const {
        for (const auto& [key, value] : flags) {
            if (key == name) return value;
        }
        return std::nullopt;
    }
};

std::optional<Arguments> parse(int argc, char** argv, const std::vector<std::string>& known,
                               std::string& problem) {
    Arguments arguments;
    for (int i = 2; i < argc; ++i) {
        std::string argument = argv[i];
        if (argument.rfind("--", 0) != 0) {
            arguments.positional.push_back(argument);
            continue;
        }
        bool isKnown = false;
        for (const std::string& name : known)
            isKnown = isKnown || name == argument;
        if (!isKnown) {
            problem = "unknown option " + argument;
            return std::nullopt;
        }
        if (i + 1 >= argc) {
            problem = argument + " needs a value";
            return std::nullopt;
        }
        arguments.flags.emplace_back(argument, argv[++i]);
    }
    return arguments;
}

int check(const Arguments& arguments) {
    if (arguments.positional.size() != 1) return usage("check takes one golden name");
    std::optional<std::string> actual = arguments.flag("--actual-dir");
    std::optional<std::string> expected = arguments.flag("--expected-dir");
    if (!actual || !expected) return usage("check needs --actual-dir and --expected-dir");
    CheckRequest request;
    request.name = arguments.positional[0];
    request.actualDir = *actual;
    request.expectedDir = *expected;
    request.outputDir = arguments.flag("--output-dir").value_or("");
    return checkGolden(request, std::cout);
}

int compare(const Arguments& arguments) {
    if (arguments.positional.size() != 2) return usage("compare takes two image files");
    std::optional<std::filesystem::path> diff;
    if (auto value = arguments.flag("--diff")) diff = *value;
    return compareImageFiles(arguments.positional[0], arguments.positional[1], diff,
                             GoldenThresholds{}, std::cout);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage("no command");
    const std::string command = argv[1];
    if (command == "--help" || command == "-h") {
        std::cout << kUsage;
        return kExitPass;
    }
    std::string problem;
    if (command == "check") {
        auto arguments =
            parse(argc, argv, {"--actual-dir", "--expected-dir", "--output-dir"}, problem);
        return arguments ? check(*arguments) : usage(problem);
    }
    if (command == "compare") {
        auto arguments = parse(argc, argv, {"--diff"}, problem);
        return arguments ? compare(*arguments) : usage(problem);
    }
    if (command == "inspect") {
        if (argc != 3) return usage("inspect takes one .exr file");
        return inspectExr(argv[2], std::cout);
    }
    return usage("unknown command '" + command + "'");
}
