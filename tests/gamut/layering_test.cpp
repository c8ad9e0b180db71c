// irid_gamut needs irid_color only (docs/DESIGN.md: the arrows point down; clipping knows no
// physics): none of its sources or public headers includes a header of another irid library.
// The link line does not enforce it (every library shares the include folder), so this reads
// the files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// The irid module of an `#include <irid/MODULE/...>` line, or "" for any other line.
std::string included_module(const std::string& line) {
    const std::string prefix = "#include <irid/";
    const std::size_t at = line.find(prefix);
    if (at == std::string::npos || line.find_first_not_of(" \t") != at) return "";
    const std::size_t begin = at + prefix.size();
    const std::size_t slash = line.find('/', begin), close = line.find('>', begin);
    if (slash == std::string::npos || slash > close) return "";  // <irid/error.h>: the shared core
    return line.substr(begin, slash - begin);
}

TEST(GamutLayer, IncludesNoHeaderOfALibraryAboveTheColourCore) {
    const std::filesystem::path root(IRID_SOURCE_DIR);
    std::vector<std::string> offending;
    std::size_t files = 0;
    for (const char* folder : {"include/irid/gamut", "src/gamut"}) {
        for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
            std::ifstream in(entry.path());
            ASSERT_TRUE(in) << entry.path();
            ++files;
            std::string line;
            int number = 0;
            while (std::getline(in, line)) {
                ++number;
                const std::string module = included_module(line);
                if (!module.empty() && module != "color" && module != "gamut") {
                    offending.push_back(entry.path().string() + ":" + std::to_string(number) +
                                        ": " + line);
                }
            }
        }
    }
    EXPECT_GE(files, 9u);  // clip, batch, batch_simd, report, analysis and their headers
    std::ostringstream all;
    for (const std::string& o : offending) all << "\n  " << o;
    EXPECT_TRUE(offending.empty()) << "irid_gamut includes other libraries' headers:" << all.str();
}

TEST(GamutLayer, TheIncludeParserRecognisesModules) {
    EXPECT_EQ(included_module("#include <irid/optics/film_color.h>"), "optics");
    EXPECT_EQ(included_module("#include <irid/color/rgb.h>"), "color");
    EXPECT_EQ(included_module("#include <irid/error.h>"), "");
    EXPECT_EQ(included_module("// #include <irid/optics/material.h>"), "");
    EXPECT_EQ(included_module("#include <vector>"), "");
}

}  // namespace
