// The stack (docs/DESIGN.md): each library includes only the headers of the libraries below it.
// The link line does not enforce that (every library shares the include folder), so this reads
// the files: every header and source of every library, against one table of what each may
// include, and the table against the libraries CMakeLists.txt links each one to.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// The stack, bottom up: each library and the libraries whose headers it may include (besides
/// its own and the shared ones directly in include/irid/: error.h, parallel.h, ...).
const std::map<std::string, std::set<std::string>> allowed = {
    {"color", {}},
    {"io", {}},
    {"texture", {}},
    {"optics", {"color"}},
    {"gamut", {"color"}},
    {"exchange", {"color", "gamut", "io"}},
    {"figures", {"color", "optics", "gamut", "io"}},
    {"render", {"color", "optics", "gamut", "io", "texture"}},
    {"gallery", {"color", "optics", "gamut", "io", "texture", "figures", "render"}},
};

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

/// The irid libraries `target_link_libraries(irid_NAME ...)` names in CMakeLists.txt, per library.
std::map<std::string, std::set<std::string>> linked_libraries(const std::string& cmake) {
    std::map<std::string, std::set<std::string>> links;
    const std::string call = "target_link_libraries(irid_";
    for (std::size_t at = cmake.find(call); at != std::string::npos; at = cmake.find(call, at + 1)) {
        const std::size_t close = cmake.find(')', at);
        std::istringstream words(cmake.substr(at + call.size(), close - at - call.size()));
        std::string name, word;
        words >> name;
        while (words >> word) {
            if (word.rfind("irid_", 0) == 0) links[name].insert(word.substr(5));
        }
    }
    return links;
}

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(Layering, EveryLibraryIncludesOnlyTheLibrariesBelowIt) {
    const std::filesystem::path root(IRID_SOURCE_DIR);
    std::vector<std::string> offending;
    std::map<std::string, std::size_t> files;
    for (const auto& [module, below] : allowed) {
        for (const std::filesystem::path& folder : {root / "include/irid" / module, root / "src" / module}) {
            if (!std::filesystem::exists(folder)) continue;
            for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
                if (!entry.is_regular_file()) continue;
                std::ifstream in(entry.path());
                ASSERT_TRUE(in) << entry.path();
                ++files[module];
                std::string line;
                int number = 0;
                while (std::getline(in, line)) {
                    ++number;
                    const std::string m = included_module(line);
                    if (!m.empty() && m != module && !below.contains(m)) {
                        offending.push_back(entry.path().lexically_relative(root).string() + ":" +
                                            std::to_string(number) + ": " + line + "  (" + module +
                                            " may include: itself" +
                                            std::accumulate(below.begin(), below.end(), std::string(),
                                                            [](std::string a, const std::string& b) {
                                                                return std::move(a) + ", " + b;
                                                            }) +
                                            ")");
                    }
                }
            }
        }
        EXPECT_GT(files[module], 0u) << module << " has no files: is the table out of date?";
    }
    std::ostringstream all;
    for (const std::string& o : offending) all << "\n  " << o;
    EXPECT_TRUE(offending.empty()) << "headers included from above the stack:" << all.str();
}

TEST(Layering, EveryLibraryIsInTheTable) {
    // A new folder under include/irid or src is a new library: it must take its place in the
    // stack above before anything can include it.
    const std::filesystem::path root(IRID_SOURCE_DIR);
    for (const std::filesystem::path& folder : {root / "include/irid", root / "src"}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (!entry.is_directory()) continue;
            EXPECT_TRUE(allowed.contains(entry.path().filename().string()))
                << entry.path().lexically_relative(root) << " is not in the layering table";
        }
    }
}

TEST(Layering, TheTableAgreesWithTheBuild) {
    // What a library may include, it links (directly or through what it links): the table
    // cannot allow what the build does not provide, and a library linking one above it in the
    // table (a cycle) is caught as an include the table refuses.
    const auto links = linked_libraries(read(std::filesystem::path(IRID_SOURCE_DIR) / "CMakeLists.txt"));
    const auto reach = [&](const std::string& module) {
        std::set<std::string> seen;
        std::vector<std::string> todo{module};
        while (!todo.empty()) {
            const std::string m = todo.back();
            todo.pop_back();
            const auto it = links.find(m);
            if (it == links.end()) continue;
            for (const std::string& l : it->second) {
                if (seen.insert(l).second) todo.push_back(l);
            }
        }
        return seen;
    };
    for (const auto& [module, below] : allowed) {
        const std::set<std::string> linked = reach(module);
        for (const std::string& b : below) {
            EXPECT_TRUE(linked.contains(b)) << "irid_" << module << " may include " << b << " but does not link irid_" << b;
        }
        // And it links nothing above it in the stack (warnings is the build's flags, not a library).
        for (const std::string& l : linked) {
            EXPECT_TRUE(l == "warnings" || below.contains(l)) << "irid_" << module << " links irid_" << l
                                                                << ", which the table puts above it";
        }
    }
}

TEST(Layering, TheIncludeParserRecognisesModules) {
    EXPECT_EQ(included_module("#include <irid/optics/film_color.h>"), "optics");
    EXPECT_EQ(included_module("#include <irid/color/rgb.h>"), "color");
    EXPECT_EQ(included_module("#include <irid/error.h>"), "");
    EXPECT_EQ(included_module("// #include <irid/optics/material.h>"), "");
    EXPECT_EQ(included_module("#include <vector>"), "");
    const auto links = linked_libraries("target_link_libraries(irid_a PUBLIC irid_b\n  PRIVATE fmt::fmt irid_c)\n"
                                        "target_link_libraries(other PRIVATE irid_d)");
    ASSERT_EQ(links.size(), 1u);
    EXPECT_EQ(links.at("a"), (std::set<std::string>{"b", "c"}));
}

}  // namespace
