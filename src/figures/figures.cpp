#include <irid/error.h>
#include <irid/figures/figures.h>

#include "figure_support.h"

#include <algorithm>
#include <vector>

namespace irid::figures {

std::span<const FigureInfo> figure_catalog() {
    static const std::vector<FigureInfo> infos = [] {
        std::vector<FigureInfo> out;
        for (const detail::CatalogEntry& e : detail::catalog_entries()) out.push_back(e.info);
        return out;
    }();
    return infos;
}

const FigureInfo* find_figure(std::string_view name) noexcept {
    for (const FigureInfo& info : figure_catalog()) {
        if (info.name == name) return &info;
    }
    return nullptr;
}

FigureResult draw_figure(const FigureRequest& request) {
    const detail::CatalogEntry* entry = nullptr;
    for (const detail::CatalogEntry& e : detail::catalog_entries()) {
        if (e.info.name == request.name) entry = &e;
    }
    if (entry == nullptr) {
        std::vector<std::string> names;
        for (const detail::CatalogEntry& e : detail::catalog_entries()) names.push_back(e.info.name);
        throw FigureRequestError("unknown figure \"" + request.name + "\"; valid names: " +
                    detail::join(names, ", "));
    }
    const std::string ext = detail::lower_extension(request.output);
    const auto& allowed = entry->info.extensions;
    if (std::find(allowed.begin(), allowed.end(), ext) == allowed.end()) {
        throw FigureRequestError(request.name + ": output " + request.output.string() +
                    ": unsupported extension \"" + ext + "\"; allowed: " +
                    detail::join(allowed, ", "));
    }
    const bool is_image = ext == ".svg" || ext == ".png";
    if (is_image && (request.width_px < min_size_px || request.width_px > max_size_px ||
                     request.height_px < min_size_px || request.height_px > max_size_px)) {
        throw FigureRequestError(request.name + ": image size " + std::to_string(request.width_px) + "x" +
                    std::to_string(request.height_px) + " is outside the allowed " +
                    std::to_string(min_size_px) + ".." + std::to_string(max_size_px) +
                    " per side (width and height)");
    }
    FigureResult result = entry->draw(request);
    if (is_image && result.width_px == 0) {
        result.width_px = request.width_px;
        result.height_px = request.height_px;
    }
    return result;
}

std::string html_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace irid::figures
