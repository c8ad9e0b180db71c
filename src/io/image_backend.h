#pragma once

// The OpenImageIO backend of irid_io, built as a module (libirid_oiio.so) and loaded with dlopen
// on the first image read or write. Linking OpenImageIO into a program costs about 0.2 s at
// every start (the static initialisers of its ~250 libraries), which every irid command would
// pay; loaded on demand, only image work pays it.
//
// The module and irid_io are built together by the same compiler and standard library, so the
// table passes C++ types; errors come back as messages, never as exceptions across the boundary.

#include <irid/io/image.h>
#include <irid/io/output_file.h>

#include <string>

namespace irid::io {

/// Bumped whenever ImageBackend, Image or ImageEncoding change layout.
inline constexpr int image_backend_abi_version = 4;

struct ImageBackend {
    int abi_version;
    bool (*read)(const char* path, const ImageLimits* limits, Image* out,
                 std::string* error) noexcept;
    /// Writes into an open output; the caller commits it.
    bool (*write)(OutputFile* file, const Image* image, const ImageEncoding* encoding,
                  std::string* error) noexcept;
};

}  // namespace irid::io

/// The module's one exported symbol.
extern "C" const irid::io::ImageBackend* irid_image_backend();
