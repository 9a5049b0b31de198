// A fuzzer over what a scene file sets (issue 44): its top-level settings block, a material
// override, the camera, a light, the fog and the atmosphere, with numbers drawn from the
// float edge cases (+-0, denormals, 1e-45, 3e38, Inf, NaN, huge integers). Each input is a
// scene file that `candela run` renders as two 32x32 frames; an input fails when the process
// dies (a signal, a sanitizer report), a validation message appears, or a frame holds a
// non-finite pixel. A refused file (an error, exit 1 without those) is a pass: refusing is
// what the engine should do with what it cannot render.
//
//   fuzz_frame_settings --candela PATH [--seconds N] [--seed S] [--out DIR] [FILE.scene.json...]
// With files: replays them (a found input, or tests/runtime/settings_regressions/); without:
// random inputs until the time is spent. Exit 1 when an input failed (saved in --out).
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

const double kEdgeValues[] = {
    0.0,           -0.0,         std::numeric_limits<float>::denorm_min(),
    1e-45,         1e-38,        1e-30,
    1e-6,          0.5,          1.0,
    -1.0,          2.0,          1e6,
    1e20,          3e38,         -3e38,
    1e300,         2147483647.0, 4294967296.0,
    -2147483648.0,
    // Inf and NaN are not JSON: written as the strings the reader must refuse, and as 1e999
    // (which nlohmann reads as Inf).
};

// A JSON pointer into the base scene and how to mutate it: a number, or a choice of names.
struct Field {
    const char* pointer;
    std::vector<const char*> names;  // empty: a number
};

const Field kFields[] = {
    {"/bloom", {}},
    {"/exposure_compensation", {}},
    {"/msaa", {}},
    {"/ambient_occlusion/radius", {}},
    {"/ambient_occlusion/intensity", {}},
    {"/quality", {"low", "medium", "high", "ultra"}},
    {"/aa", {"off", "fxaa", "taa", "gbaa"}},
    {"/ssr", {"off", "hiz", "reference"}},
    {"/volumetrics", {"off", "volumes", "froxels", "reference"}},
    {"/scattering", {"off", "epipolar", "brute-force"}},
    {"/exposure", {"manual", "auto"}},
    {"/entities/0/materialOverrides/0/material/metallicFactor", {}},
    {"/entities/0/materialOverrides/0/material/roughnessFactor", {}},
    {"/entities/0/materialOverrides/0/material/emissiveStrength", {}},
    {"/entities/0/materialOverrides/0/material/emissiveFactor/0", {}},
    {"/entities/0/materialOverrides/0/material/baseColorFactor/1", {}},
    {"/entities/0/materialOverrides/0/material/normalScale", {}},
    {"/entities/0/materialOverrides/0/material/specular", {}},
    {"/entities/0/materialOverrides/0/material/occlusionStrength", {}},
    {"/entities/0/materialOverrides/0/material/baseColorTexture/texture", {}},
    {"/entities/0/materialOverrides/0/material/baseColorTexture/scale/0", {}},
    {"/entities/0/materialOverrides/0/material/baseColorTexture/rotation", {}},
    {"/entities/0/transform/scale/1", {}},
    {"/entities/1/light/lumens", {}},
    {"/entities/1/light/attenuationRadius", {}},
    {"/entities/1/light/sourceRadius", {}},
    {"/entities/1/light/sourceLength", {}},
    {"/entities/1/light/color/0", {}},
    {"/entities/1/light/outerConeAngle", {}},
    {"/entities/1/transform/translation/1", {}},
    {"/entities/2/camera/manualEv100", {}},
    {"/entities/2/camera/verticalFov", {}},
    {"/entities/2/camera/nearPlane", {}},
    {"/entities/2/camera/farPlane", {}},
    {"/entities/2/camera/aperture", {}},
    {"/entities/3/fog/scattering", {}},
    {"/entities/3/fog/absorption", {}},
    {"/entities/3/fog/anisotropy", {}},
    {"/entities/3/fog/heightFalloff", {}},
    {"/entities/3/fog/baseHeight", {}},
    {"/entities/4/atmosphere/rayleighScattering/0", {}},
    {"/entities/4/atmosphere/mieScattering", {}},
    {"/entities/4/atmosphere/mieAnisotropy", {}},
    {"/entities/4/atmosphere/solarIlluminance", {}},
    {"/entities/4/atmosphere/groundRadius", {}},
};

json baseScene(const std::string& box) {
    json material = {
        {"metallicFactor", 0.0},
        {"roughnessFactor", 0.6},
        {"emissiveStrength", 1.0},
        {"emissiveFactor", {0.0, 0.0, 0.0}},
        {"baseColorFactor", {0.7, 0.7, 0.7, 1.0}},
        {"normalScale", 1.0},
        {"specular", 0.5},
        {"occlusionStrength", 1.0},
        {"baseColorTexture", {{"texture", -1}, {"scale", {1.0, 1.0}}, {"rotation", 0.0}}}};
    return {
        {"format", "candela.scene"},
        {"version", 1},
        {"bloom", 0.04},
        {"exposure_compensation", 0.0},
        {"msaa", 1},
        {"ambient_occlusion", {{"radius", 0.5}, {"intensity", 1.0}}},
        {"entities",
         {{{"name", "floor"},
           {"mesh", {{"gltf", box}, {"mesh", 0}}},
           {"materialOverrides", {{{"primitive", 0}, {"material", material}}}},
           {"transform", {{"translation", {0, -0.5, 0}}, {"scale", {10, 1, 10}}}}},
          {{"name", "spot"},
           {"light",
            {{"type", "spot"},
             {"lumens", 8000.0},
             {"attenuationRadius", 15.0},
             {"sourceRadius", 0.1},
             {"sourceLength", 0.0},
             {"color", {1.0, 1.0, 1.0}},
             {"innerConeAngle", 0.3},
             {"outerConeAngle", 0.5}}},
           {"transform",
            {{"translation", {0, 4, 0}}, {"rotation", {-0.7071068, 0, 0, 0.7071068}}}}},
          {{"name", "camera"},
           {"camera",
            {{"manualEv100", 8.0},
             {"verticalFov", 0.8},
             {"nearPlane", 0.1},
             {"farPlane", 100.0},
             {"aperture", 16.0}}},
           {"transform", {{"translation", {0, 3, 8}}, {"rotation", {-0.17, 0, 0, 0.985}}}}},
          {{"name", "fog"},
           {"fog",
            {{"scattering", 0.05},
             {"absorption", 0.01},
             {"anisotropy", 0.3},
             {"heightFalloff", 0.2},
             {"baseHeight", 0.0}}}},
          {{"name", "air"},
           {"atmosphere",
            {{"rayleighScattering", {5.8e-6, 13.5e-6, 33.1e-6}},
             {"mieScattering", 3.996e-6},
             {"mieAnisotropy", 0.8},
             {"solarIlluminance", 100000.0},
             {"groundRadius", 6360000.0}}}}}},
    };
}

// One input: the base scene with 1 to 4 fields set to edge values.
std::string randomScene(std::mt19937_64& random, const std::string& box) {
    json scene = baseScene(box);
    const int mutations = 1 + int(random() % 4);
    for (int m = 0; m < mutations; ++m) {
        const Field& field = kFields[random() % std::size(kFields)];
        const json::json_pointer at(field.pointer);
        if (!field.names.empty()) {
            scene[at] = field.names[random() % field.names.size()];
            continue;
        }
        const size_t pick = random() % (std::size(kEdgeValues) + 3);
        if (pick < std::size(kEdgeValues)) {
            scene[at] = kEdgeValues[pick];
        } else if (pick == std::size(kEdgeValues)) {
            scene[at] = "nan";  // a string where a number belongs
        } else {
            scene[at] = 0.0;  // replaced below by a JSON number that overflows to +-Inf
            std::string text = scene.dump();
            const std::string needle = "\"" + at.back() + "\":0.0";
            if (auto where = text.find(needle); where != std::string::npos) {
                text.replace(where, needle.size(),
                             "\"" + at.back() +
                                 "\":" + (pick == std::size(kEdgeValues) + 1 ? "1e999" : "-1e999"));
                return text;
            }
        }
    }
    return scene.dump(1);
}

struct Outcome {
    bool failed = false;
    std::string why;
};

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Outcome render(const std::string& candela, const std::filesystem::path& scene,
               const std::filesystem::path& work) {
    const std::filesystem::path stats = work / "stats.json";
    const std::filesystem::path log = work / "log.txt";
    std::filesystem::remove(stats);
    const std::string command = candela + " run '" + scene.string() +
                                "' --headless --size 32x32 --frames 2 --stats '" + stats.string() +
                                "' > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    const std::string output = readText(log);
    if (!WIFEXITED(status)) {
        return {true, "killed by signal " + std::to_string(WTERMSIG(status)) + "\n" + output};
    }
    const int code = WEXITSTATUS(status);
    for (const char* bad : {"not finite", "validation error", "validation warning",
                            "AddressSanitizer", "runtime error:", "LeakSanitizer"}) {
        if (output.find(bad) != std::string::npos) {
            return {true, "exit " + std::to_string(code) + ", '" + bad + "'\n" + output};
        }
    }
    if (code > 2) return {true, "exit " + std::to_string(code) + "\n" + output};
    if (code == 0) {
        try {
            const json s = json::parse(readText(stats));
            if (s.value("validation_messages", 0) != 0 || s.value("nonfinite_pixels", 0) != 0) {
                return {true, "stats: " + s.dump().substr(0, 300) + "\n" + output};
            }
        } catch (const std::exception& e) {
            return {true,
                    std::string("exit 0 without readable stats: ") + e.what() + "\n" + output};
        }
    }
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    std::string candela;
    double seconds = 30;
    uint64_t seed = std::random_device{}();
    std::filesystem::path out = std::filesystem::temp_directory_path() / "fuzz_frame_settings";
    std::vector<std::filesystem::path> replay;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--candela" && hasValue) {
            candela = argv[++i];
        } else if (arg == "--seconds" && hasValue) {
            seconds = std::atof(argv[++i]);
        } else if (arg == "--seed" && hasValue) {
            seed = std::strtoull(argv[++i], nullptr, 10);
        } else if (arg == "--out" && hasValue) {
            out = argv[++i];
        } else {
            replay.push_back(arg);
        }
    }
    const char* assets = std::getenv("CANDELA_SHARED_ASSETS");
    if (candela.empty() || !assets) {
        std::fprintf(stderr,
                     "usage: CANDELA_SHARED_ASSETS=DIR fuzz_frame_settings --candela PATH "
                     "[--seconds N] [--seed S] [--out DIR] [FILE...]\n");
        return 2;
    }
    const std::string box = std::string(assets) + "/models/Box/Box.glb";
    std::filesystem::create_directories(out);
    const std::filesystem::path work = out / "work";
    std::filesystem::create_directories(work);
    int inputs = 0, failures = 0;
    auto run = [&](const std::filesystem::path& scene, const std::string& name) {
        ++inputs;
        const Outcome o = render(candela, scene, work);
        if (!o.failed) return;
        ++failures;
        const std::filesystem::path kept = out / ("failed-" + name + ".scene.json");
        std::filesystem::copy_file(scene, kept, std::filesystem::copy_options::overwrite_existing);
        std::fprintf(stderr, "!! %s failed: %s\n   kept as %s\n", scene.c_str(),
                     o.why.substr(0, 2000).c_str(), kept.c_str());
    };
    if (!replay.empty()) {
        for (const std::filesystem::path& file : replay) {
            // The regressions name the box as BOX: the assets folder differs between machines.
            std::string text = readText(file);
            for (size_t at; (at = text.find("\"BOX\"")) != std::string::npos;)
                text.replace(at, 5, json(box).dump());
            const std::filesystem::path scene = work / file.filename();
            std::ofstream(scene) << text;
            run(scene, file.stem().string());
        }
    } else {
        std::printf("fuzz_frame_settings: seed %llu, %.0f s\n", (unsigned long long)seed, seconds);
        std::mt19937_64 random(seed);
        const auto start = std::chrono::steady_clock::now();
        while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
               seconds) {
            const std::filesystem::path scene = work / "input.scene.json";
            std::ofstream(scene) << randomScene(random, box);
            run(scene, std::to_string(seed) + "-" + std::to_string(inputs));
        }
    }
    std::printf("fuzz_frame_settings: %d inputs, %d failed\n", inputs, failures);
    return failures ? 1 : 0;
}
