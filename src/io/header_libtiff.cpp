// A TIFF's directories read by libtiff itself before OpenImageIO reads the file
// (header_reader.h): OpenImageIO 2.4 reads the first directory and ignores libtiff's complaints
// about it and about the chain of directories after it, which libtiff's own tools (tiffinfo,
// tiffcp) refuse: a tag value out of its range ("Bad value 41729 for Orientation"), a next-IFD
// offset that points at no directory, a loop of directories.
#include "header_reader.h"

#include <cstdarg>
#include <cstdio>
#include <memory>
#include <string>

#include <tiffio.h>

namespace irid::io::header {
namespace {

/// libtiff's first error (its warnings are not kept).
int keep_first_error(TIFF*, void* user_data, const char* module, const char* format, va_list ap) {
    auto& first = *static_cast<std::string*>(user_data);
    if (first.empty()) {
        char text[512];
        std::vsnprintf(text, sizeof text, format, ap);
        first = (module != nullptr && *module != '\0' ? std::string(module) + ": " : std::string()) + text;
    }
    return 1;
}

int ignore_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

}  // namespace

void check_tiff_directories(const std::string& shown, const std::filesystem::path& path) {
    std::string first_error;
    const std::unique_ptr<TIFFOpenOptions, void (*)(TIFFOpenOptions*)> options(TIFFOpenOptionsAlloc(),
                                                                              TIFFOpenOptionsFree);
    if (!options) return;
    TIFFOpenOptionsSetErrorHandlerExtR(options.get(), keep_first_error, &first_error);
    TIFFOpenOptionsSetWarningHandlerExtR(options.get(), ignore_warning, nullptr);
    // A directory's arrays within what the header checks allow; a larger single allocation is
    // an error of its own.
    TIFFOpenOptionsSetMaxSingleMemAlloc(options.get(), tmsize_t{256} << 20);
    // "h": the header only; the first directory is read below like every other.
    const std::unique_ptr<TIFF, void (*)(TIFF*)> tif(TIFFOpenExt(path.c_str(), "rh", options.get()), TIFFClose);
    if (tif && first_error.empty()) {
        // Every directory of the chain (libtiff stops at a loop, with an error).
        for (int n = 0; n < 65536 && first_error.empty() && TIFFReadDirectory(tif.get()) != 0; ++n) {
        }
    }
    if (!first_error.empty()) corrupt(shown, "libtiff: " + first_error);
}

}  // namespace irid::io::header
