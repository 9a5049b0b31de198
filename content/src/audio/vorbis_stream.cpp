#include <vorbis/vorbisfile.h>

#include <algorithm>
#include <cstring>

#include "vorbis_stream.h"

namespace candela::content {
namespace {

// libvorbisfile reads through callbacks: these read the clip's bytes in memory.
struct MemoryFile {
    const unsigned char* data = nullptr;
    std::size_t size = 0, position = 0;
};

std::size_t readBytes(void* into, std::size_t size, std::size_t count, void* source) {
    auto& file = *static_cast<MemoryFile*>(source);
    if (size == 0) return 0;
    const std::size_t items = std::min(count, (file.size - file.position) / size);
    std::memcpy(into, file.data + file.position, items * size);
    file.position += items * size;
    return items;
}

int seekBytes(void* source, ogg_int64_t offset, int whence) {
    auto& file = *static_cast<MemoryFile*>(source);
    const ogg_int64_t base = whence == SEEK_SET   ? 0
                             : whence == SEEK_CUR ? ogg_int64_t(file.position)
                                                  : ogg_int64_t(file.size);
    const ogg_int64_t to = base + offset;
    if (to < 0 || to > ogg_int64_t(file.size)) return -1;
    file.position = std::size_t(to);
    return 0;
}

long tellBytes(void* source) {
    return long(static_cast<MemoryFile*>(source)->position);
}

}  // namespace

struct VorbisStream::Impl {
    MemoryFile file;
    OggVorbis_File vorbis{};
    bool open = false;
    std::uint32_t channels = 0;

    ~Impl() {
        if (open) ov_clear(&vorbis);
    }
};

VorbisStream::VorbisStream(std::span<const std::byte> bytes) : impl_(std::make_unique<Impl>()) {
    impl_->file = {reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0};
    const ov_callbacks callbacks{readBytes, seekBytes, nullptr, tellBytes};
    const int opened = ov_open_callbacks(&impl_->file, &impl_->vorbis, nullptr, 0, callbacks);
    if (opened != 0) {
        error_ =
            "not a readable Ogg Vorbis stream (libvorbisfile error " + std::to_string(opened) + ")";
        return;
    }
    impl_->open = true;
    const vorbis_info* info = ov_info(&impl_->vorbis, -1);
    impl_->channels = info ? std::uint32_t(std::max(info->channels, 0)) : 0;
}

VorbisStream::~VorbisStream() = default;

bool VorbisStream::ok() const {
    return impl_->open;
}

std::uint32_t VorbisStream::channels() const {
    return impl_->channels;
}

std::uint32_t VorbisStream::sampleRate() const {
    const vorbis_info* info = impl_->open ? ov_info(&impl_->vorbis, -1) : nullptr;
    return info && info->rate > 0 ? std::uint32_t(info->rate) : 0;
}

std::uint64_t VorbisStream::frames() const {
    const ogg_int64_t total = impl_->open ? ov_pcm_total(&impl_->vorbis, -1) : 0;
    return total > 0 ? std::uint64_t(total) : 0;
}

std::size_t VorbisStream::read(float* out, std::size_t frames) {
    if (!impl_->open || impl_->channels == 0) return 0;
    std::size_t done = 0;
    while (done < frames) {
        float** pcm = nullptr;
        int section = 0;
        const long got = ov_read_float(&impl_->vorbis, &pcm,
                                       int(std::min<std::size_t>(frames - done, 4096)), &section);
        if (got <= 0) break;  // the end, or damage it cannot decode past
        // A chained file whose next stream has other channels ends the clip there.
        const vorbis_info* info = ov_info(&impl_->vorbis, section);
        if (!info || std::uint32_t(info->channels) != impl_->channels) break;
        for (long f = 0; f < got; ++f)
            for (std::uint32_t c = 0; c < impl_->channels; ++c)
                out[(done + std::size_t(f)) * impl_->channels + c] = pcm[c][f];
        done += std::size_t(got);
    }
    return done;
}

void VorbisStream::rewind() {
    if (impl_->open) ov_pcm_seek(&impl_->vorbis, 0);
}

}  // namespace candela::content
