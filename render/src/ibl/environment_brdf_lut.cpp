#include "ibl/environment_brdf_lut.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>

#include "candela/content/atomic_file_write.h"
#include "candela/render/gpu_context.h"
#include "candela/render/pipeline.h"
#include "cpu_clock.h"
#include "ibl/environment_cache.h"
#include "ibl/ibl_bindings.h"
#include "shaders/environment_brdf_lut.comp.spv.h"
#include "vk/memory_barrier.h"
#include "vk/sampler.h"

namespace candela::render {

namespace {

constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_UNORM;
constexpr char kMagic[8] = {'C', 'A', 'N', 'D', 'B', 'L', 'U', 'T'};

// What determines the texels: the shader's SPIR-V, its size and sample count, the format and
// the cache version. A file whose key differs is another LUT (its name differs too).
uint64_t cacheKey() {
    uint64_t h = fnv1a64(environment_brdf_lut_comp_spv, sizeof(environment_brdf_lut_comp_spv));
    const uint32_t parameters[] = {EnvironmentBrdfLut::kCacheVersion, EnvironmentBrdfLut::kSize,
                                   EnvironmentBrdfLut::kSampleCount, uint32_t(kFormat)};
    return fnv1a64(parameters, sizeof(parameters), h);
}

struct CacheHeader {
    char magic[8];
    uint64_t key;
    uint64_t payloadBytes;
    uint64_t payloadChecksum;
};

// Empty on success; otherwise why the file cannot be used (empty `texels` when it is absent).
std::string readCacheFile(const std::filesystem::path& path, std::vector<uint32_t>& texels,
                          size_t expectedBytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        return std::filesystem::exists(path, ec) ? "not a regular file" : "";
    }
    const std::uintmax_t fileBytes = std::filesystem::file_size(path, ec);
    if (ec) return "cannot stat: " + ec.message();
    if (fileBytes != sizeof(CacheHeader) + expectedBytes) return "wrong size (truncated?)";
    std::ifstream in(path, std::ios::binary);
    CacheHeader h{};
    if (!in || !in.read(reinterpret_cast<char*>(&h), sizeof(h))) return "unreadable";
    if (std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0 || h.key != cacheKey() ||
        h.payloadBytes != expectedBytes) {
        return "not a BRDF LUT entry of this version";
    }
    texels.resize(expectedBytes / sizeof(uint32_t));
    if (!in.read(reinterpret_cast<char*>(texels.data()), std::streamsize(expectedBytes))) {
        texels.clear();
        return "truncated";
    }
    if (fnv1a64(texels.data(), expectedBytes) != h.payloadChecksum) {
        texels.clear();
        return "checksum mismatch";
    }
    return "";
}

std::string writeCacheFile(const std::filesystem::path& path, const uint32_t* texels,
                           size_t bytes) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) return "cannot create " + path.parent_path().string() + ": " + ec.message();
    CacheHeader h{};
    std::memcpy(h.magic, kMagic, sizeof(kMagic));
    h.key = cacheKey();
    h.payloadBytes = bytes;
    h.payloadChecksum = fnv1a64(texels, bytes);
    std::string data(reinterpret_cast<const char*>(&h), sizeof(h));
    data.append(reinterpret_cast<const char*>(texels), bytes);
    return content::writeFileAtomically(path, data);
}

// The texels of this process's last LUT and the folder they belong to: a renderer created
// again (editor, tests) uploads them instead of reading the file.
struct ProcessCopy {
    std::mutex mutex;
    std::filesystem::path directory;
    std::vector<uint32_t> texels;
};

ProcessCopy& processCopy() {
    static ProcessCopy copy;
    return copy;
}

}  // namespace

std::filesystem::path EnvironmentBrdfLut::cachePath(const std::filesystem::path& cacheDirectory) {
    char name[48];
    std::snprintf(name, sizeof(name), "brdf-lut-%016llx.cibl",
                  static_cast<unsigned long long>(cacheKey()));
    return cacheDirectory / name;
}

std::unique_ptr<EnvironmentBrdfLut> EnvironmentBrdfLut::loadOrBuild(
    GpuContext& context, const std::filesystem::path& cacheDirectory,
    std::vector<std::string>& warnings) {
    const CpuClock::time_point start = CpuClock::now();
    ProcessCopy& copy = processCopy();
    std::lock_guard lock(copy.mutex);
    std::unique_ptr<EnvironmentBrdfLut> lut;
    if (!cacheDirectory.empty() && copy.directory == cacheDirectory &&
        copy.texels.size() * sizeof(uint32_t) == kTexelBytes) {
        lut.reset(new EnvironmentBrdfLut(context, copy.texels.data(), Source::ProcessCache));
        lut->buildMs_ = millisecondsSince(start);
        return lut;
    }
    if (cacheDirectory.empty()) return std::make_unique<EnvironmentBrdfLut>(context);

    const std::filesystem::path path = cachePath(cacheDirectory);
    std::vector<uint32_t> texels;
    if (std::string problem = readCacheFile(path, texels, kTexelBytes); !problem.empty()) {
        warnings.push_back(path.string() + ": ignoring BRDF LUT cache entry (" + problem +
                           "); rebuilding");
    }
    if (!texels.empty()) {
        lut.reset(new EnvironmentBrdfLut(context, texels.data(), Source::DiskCache));
        lut->buildMs_ = millisecondsSince(start);
    } else {
        lut = std::make_unique<EnvironmentBrdfLut>(context);
        texels.assign(lut->packedTexels(), lut->packedTexels() + kTexelBytes / sizeof(uint32_t));
        if (std::string e = writeCacheFile(path, texels.data(), kTexelBytes); !e.empty()) {
            warnings.push_back(path.string() + ": BRDF LUT cache not written: " + e);
        }
    }
    copy.directory = cacheDirectory;
    copy.texels = std::move(texels);
    return lut;
}

const char* EnvironmentBrdfLut::sourceName() const {
    switch (source_) {
        case Source::DiskCache:
            return "disk_cache";
        case Source::ProcessCache:
            return "process_cache";
        case Source::Built:
            break;
    }
    return "built";
}

EnvironmentBrdfLut::EnvironmentBrdfLut(GpuContext& context)
    : EnvironmentBrdfLut(context, nullptr, Source::Built) {}

// With `cachedTexels`, the same bytes the shader wrote are uploaded instead: the image is
// identical bit for bit.
EnvironmentBrdfLut::EnvironmentBrdfLut(GpuContext& context, const uint32_t* cachedTexels,
                                       Source source)
    : image_(context, {kFormat, kSize, kSize, 1, false,
                       // TRANSFER_SRC: tests read the image back to compare cached and built.
                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT}),
      texels_(context, VkDeviceSize(kSize) * kSize * 8,
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
              MemoryLocation::HostVisible),
      sampler_(std::make_unique<Sampler>(context, SamplerDesc{VK_FILTER_LINEAR, false})),
      source_(source) {
    const CpuClock::time_point start = CpuClock::now();
    if (cachedTexels) {
        std::memcpy(texels_.mapped(), cachedTexels, kTexelBytes);
        context.submitAndWait([&](VkCommandBuffer cmd) { copyTexelsToImage(cmd); });
        return;
    }
    const DescriptorBinding bindings[] = {
        {BRDF_LUT_BINDING_TEXELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}};
    Pipeline pipeline = Pipeline::compute(context, environment_brdf_lut_comp_spv, bindings, 8);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        VkDescriptorBufferInfo out{texels_.handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet writes[] = {storageBufferWrite(BRDF_LUT_BINDING_TEXELS, &out)};
        struct {
            uint32_t size;
            uint32_t sampleCount;
        } push{kSize, kSampleCount};
        pipeline.bind(cmd);
        pipeline.pushDescriptors(cmd, writes);
        pipeline.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, kSize / 8, kSize / 8, 1);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_HOST_READ_BIT);
        copyTexelsToImage(cmd);
    });
    buildMs_ = millisecondsSince(start);
}

void EnvironmentBrdfLut::copyTexelsToImage(VkCommandBuffer cmd) {
    transitionImage(cmd, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kSize, kSize, 1};
    vkCmdCopyBufferToImage(cmd, texels_.handle(), image_.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transitionImage(cmd, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_READ_BIT);
}

EnvironmentBrdfLut::~EnvironmentBrdfLut() = default;

VkSampler EnvironmentBrdfLut::sampler() const {
    return sampler_->handle();
}

}  // namespace candela::render
