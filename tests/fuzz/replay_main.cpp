// The replay driver: runs a libFuzzer harness's LLVMFuzzerTestOneInput on every file of the
// folders (or on the files) given, in name order, with the normal compiler and no libFuzzer, so
// that the committed corpora and regressions run in every build of the test suite
// (fuzz.replay.<harness>, tests/fuzz/CMakeLists.txt).
//
//   fuzz_replay_<harness> [--optional] PATH...
//
// A PATH after --optional may be missing (a harness without regressions). Exit 0 when every
// input ran; a broken contract traps, as under libFuzzer.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    if (LLVMFuzzerInitialize != nullptr) LLVMFuzzerInitialize(&argc, &argv);
    std::vector<fs::path> files;
    bool optional = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--optional") {
            optional = true;
            continue;
        }
        const fs::path path(arg);
        std::error_code ec;
        if (fs::is_directory(path, ec)) {
            std::vector<fs::path> found;
            for (const auto& entry : fs::recursive_directory_iterator(path)) {
                if (entry.is_regular_file()) found.push_back(entry.path());
            }
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::is_regular_file(path, ec)) {
            files.push_back(path);
        } else if (!optional) {
            std::fprintf(stderr, "replay: %s: no such file or folder\n", arg.c_str());
            return 2;
        }
        optional = false;
    }
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
        if (!in.eof() && in.fail()) {
            std::fprintf(stderr, "replay: %s: cannot read\n", file.c_str());
            return 2;
        }
        std::fprintf(stderr, "replay: %s (%zu bytes)\n", file.c_str(), bytes.size());
        // A copy in its own allocation of exactly the input's size, as libFuzzer passes it, so
        // that ASan sees a read past the end.
        std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
        static const std::uint8_t no_bytes = 0;  // libFuzzer never passes a null pointer
        LLVMFuzzerTestOneInput(data.empty() ? &no_bytes : data.data(), data.size());
    }
    std::fprintf(stderr, "replay: %zu input(s) ran\n", files.size());
    return 0;
}
