#pragma once

// The gallery: every scene, figure and table of irid on one HTML page, beside the thesis'
// figure numbers, with the numbers measured while making them (`irid gallery`, and the
// library's callers). The page is plain HTML and CSS and references only the PNG and HTML
// files written beside it, so it opens from the file system without a network.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace irid::gallery {

/// A page that something else wrote into the gallery's folder (scripts/run's live three.js page,
/// iridescence.html), linked from index.html.
struct LinkedPage {
    /// Its file, relative to the gallery's folder, inside it (no "..", not absolute); it must
    /// exist when the gallery is made.
    std::filesystem::path file;
    /// The link's text.
    std::string title;
};

struct GalleryOptions {
    /// The folder to write index.html and its images into; made when missing.
    std::filesystem::path dir;
    /// The scenes' size (32..4096 × 24..4096) and samples per pixel (1..256).
    int width = 1024;
    int height = 768;
    int spp = 4;
    /// The figures' width in pixels (320..4096; height 5/8 of it).
    int figure_width = 960;
    /// Worker threads of the renders; 0 = all available.
    int threads = 0;
    /// Pages already in dir that index.html links, under "Live pages" after its introduction.
    std::vector<LinkedPage> pages;
    /// Called with a line of progress ("rendering oil-slick (1024×768, 4 spp)"); may be empty.
    std::function<void(const std::string&)> progress;
};

struct GalleryResult {
    /// dir/index.html.
    std::filesystem::path index;
    double seconds = 0;
};

/// Renders the scenes, draws the figures and tables, measures the clip report and writes the
/// page. Throws irid::Error for options out of range, a linked page that is missing or outside
/// dir, or a folder that cannot be made or written.
GalleryResult make_gallery(const GalleryOptions& options);

}  // namespace irid::gallery
