// ozz-animation's side of candela-bench-animation (issue 20's anchor). Not part of Candela's
// build: scripts/bench-animation-vs-ozz compiles it against an ozz-animation built outside
// the repository. N Foxes, each with its own sampling context, SoA local pose, model and
// skinning matrices; per frame and Fox: SamplingJob, LocalToModelJob and one product per joint
// (model x inverse bind, the skinning matrix). The crowd is timed as candela-bench-animation
// times it: one thread, thread CPU time, each Fox 0.013 s further into the clip, 1/60 s per
// frame, max(1, 1,000 / N) frames per clock pair, medians.
//   ozz_fox_bench skeleton.ozz Walk.ozz MAX_FOXES FRAMES
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "ozz/animation/runtime/animation.h"
#include "ozz/animation/runtime/local_to_model_job.h"
#include "ozz/animation/runtime/sampling_job.h"
#include "ozz/animation/runtime/skeleton.h"
#include "ozz/base/io/archive.h"
#include "ozz/base/io/stream.h"
#include "ozz/base/maths/simd_math.h"
#include "ozz/base/maths/soa_transform.h"
#include "ozz/base/span.h"

#include "../bench_frame_timing.h"

namespace {

template <class T>
bool load(const char* path, T& out) {
    ozz::io::File file(path, "rb");
    if (!file.opened()) return false;
    ozz::io::IArchive archive(&file);
    if (!archive.TestTag<T>()) return false;
    archive >> out;
    return true;
}

struct Fox {
    std::vector<ozz::math::SoaTransform> locals;
    std::vector<ozz::math::Float4x4> models;
    std::vector<ozz::math::Float4x4> skinning;
    std::unique_ptr<ozz::animation::SamplingJob::Context> context;
    float time = 0;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s skeleton.ozz animation.ozz MAX_FOXES FRAMES\n", argv[0]);
        return 2;
    }
    ozz::animation::Skeleton skeleton;
    ozz::animation::Animation animation;
    if (!load(argv[1], skeleton) || !load(argv[2], animation)) {
        std::fprintf(stderr, "ozz_fox_bench: cannot read '%s' or '%s'\n", argv[1], argv[2]);
        return 1;
    }
    const int maxFoxes = std::atoi(argv[3]);
    const int frames = std::atoi(argv[4]);
    if (maxFoxes < 1 || frames < 1) {
        std::fprintf(stderr, "ozz_fox_bench: MAX_FOXES and FRAMES must be at least 1\n");
        return 2;
    }
    const int joints = skeleton.num_joints();
    // Inverse bind matrices: the inverse of the rest pose's model matrices (ozz's files do not
    // carry the glTF skin's; their values do not change the cost).
    std::vector<ozz::math::Float4x4> inverseBind(static_cast<std::size_t>(joints));
    {
        std::vector<ozz::math::Float4x4> rest(static_cast<std::size_t>(joints));
        ozz::animation::LocalToModelJob job;
        job.skeleton = &skeleton;
        job.input = skeleton.joint_rest_poses();
        job.output = ozz::make_span(rest);
        if (!job.Run()) return 1;
        for (std::size_t j = 0; j < rest.size(); ++j)
            inverseBind[j] = ozz::math::Invert(rest[j]);
    }
    const float duration = animation.duration();
    std::printf("ozz: %d joints, %d tracks, clip %.3f s; %d frames per size, medians\n", joints,
                animation.num_tracks(), duration, frames);
    std::printf("| foxes | frame ms (one clock pair per 1,000 / foxes frames) | ns/joint |\n");
    std::printf("|---:|---:|---:|\n");
    for (int n = 1; n <= maxFoxes; n *= 10) {
        std::vector<Fox> foxes(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            Fox& fox = foxes[static_cast<std::size_t>(i)];
            fox.locals.resize(static_cast<std::size_t>(skeleton.num_soa_joints()));
            fox.models.resize(static_cast<std::size_t>(joints));
            fox.skinning.resize(static_cast<std::size_t>(joints));
            fox.context =
                std::make_unique<ozz::animation::SamplingJob::Context>(animation.num_tracks());
            fox.time = std::fmod(0.013f * static_cast<float>(i), duration);
        }
        auto frame = [&] {
            for (Fox& fox : foxes) {
                fox.time += 1.0f / 60.0f;
                if (fox.time >= duration) fox.time -= duration;
                ozz::animation::SamplingJob sampling;
                sampling.animation = &animation;
                sampling.context = fox.context.get();
                sampling.ratio = fox.time / duration;
                sampling.output = ozz::make_span(fox.locals);
                if (!sampling.Run()) std::abort();
                ozz::animation::LocalToModelJob localToModel;
                localToModel.skeleton = &skeleton;
                localToModel.input = ozz::make_span(fox.locals);
                localToModel.output = ozz::make_span(fox.models);
                if (!localToModel.Run()) std::abort();
                for (std::size_t j = 0; j < fox.models.size(); ++j)
                    fox.skinning[j] = fox.models[j] * inverseBind[j];
            }
        };
        const int batch = candela::bench::framesPerClockPair(n);
        for (int w = 0; w < 3; ++w)
            frame();
        std::vector<double> times;
        for (int f = 0; f < frames; ++f) {
            const double t0 = candela::bench::threadCpuNs();
            for (int b = 0; b < batch; ++b)
                frame();
            times.push_back((candela::bench::threadCpuNs() - t0) / batch);
        }
        const double ns = candela::bench::median(times);
        std::printf("| %d | %.6f | %.1f |\n", n, ns / 1e6,
                    ns / (static_cast<double>(n) * static_cast<double>(joints)));
    }
    return 0;
}
