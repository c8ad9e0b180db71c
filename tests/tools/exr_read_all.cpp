// exr_read_all FILE: reads every pixel of every channel of an OpenEXR file's first part through
// OpenEXR's own library (Imf::InputFile, scanline or tiled), as the judge of what a damaged EXR
// is (Debian 12's OpenEXR 3.1 has no exrcheck). Exit 0 when the whole file reads, 1 with
// OpenEXR's message when it does not, 2 on a usage error.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cstddef>
#include <cstdio>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: exr_read_all FILE\n");
        return 2;
    }
    try {
        Imf::InputFile file(argv[1]);
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        // The reader refuses what irid refuses as too large (64 Mpixel and 16 channels at most).
        if (width < 1 || height < 1 || width * height > (64ll << 20)) {
            std::fprintf(stderr, "%s: a data window of %lld x %lld pixels\n", argv[1], width, height);
            return 1;
        }
        std::vector<std::vector<float>> planes;
        Imf::FrameBuffer frame;
        for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
            if (planes.size() == 16) break;
            const Imf::Channel& ch = c.channel();
            const long long w = (width + ch.xSampling - 1) / ch.xSampling, h = (height + ch.ySampling - 1) / ch.ySampling;
            planes.emplace_back(static_cast<std::size_t>(w * h));
            // Slices are addressed from the data window's origin (OpenEXR's convention).
            char* base = reinterpret_cast<char*>(planes.back().data()) -
                         (static_cast<std::ptrdiff_t>(window.min.y / ch.ySampling) * w + window.min.x / ch.xSampling) *
                             static_cast<std::ptrdiff_t>(sizeof(float));
            frame.insert(c.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * static_cast<std::size_t>(w),
                                              ch.xSampling, ch.ySampling));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (!file.isComplete()) {
            std::fprintf(stderr, "%s: incomplete\n", argv[1]);
            return 1;
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
        return 1;
    }
    return 0;
}
