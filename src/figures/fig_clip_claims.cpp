// clip-claims: the claims of Smits 1990, §4.3.4 for the constant-lightness clip (lightness is
// constant, saturation is lower, the hue change is small except where a gamut face is nearly
// parallel to the plane of constant lightness), measured for every clip method, as a table with
// one verdict per claim.

#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/figures/clip_sets.h>
#include <irid/io/output_file.h>

#include "figure_support.h"
#include "film_clip_data.h"
#include "plot.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace irid::figures::detail {
namespace {

/// A number in a compact form: fixed decimals for ordinary sizes, scientific for tiny ones.
std::string compact(double v, int decimals = 2) {
    if (std::isnan(v)) return "—";
    if (v == 0.0) return "0";
    if (v != 0.0 && std::abs(v) < 0.5 * std::pow(10.0, -decimals)) {
        std::array<char, 32> buffer{};
        std::snprintf(buffer.data(), buffer.size(), "%.1e", v);
        return buffer.data();
    }
    return fixed(v, decimals);
}

std::string stats_text(const ClipStatistics& s) {
    if (s.count == 0) return "—";
    return compact(s.mean) + " / " + compact(s.p95) + " / " + compact(s.max);
}

std::string percent(std::size_t part, std::size_t whole) {
    if (whole == 0) return "—";
    return fixed(100.0 * static_cast<double>(part) / static_cast<double>(whole), 1) + " %";
}

/// The channels whose faces lie in a bin of face angles ("g 27.3°").
std::string bin_faces(const AngleBinHueStatistics& bin, const std::array<double, 3>& angles) {
    static constexpr const char* names[] = {"r", "g", "b"};
    std::string s;
    for (int ch = 0; ch < 3; ++ch) {
        const double a = angles[static_cast<std::size_t>(ch)];
        if (a >= bin.min_deg && (a < bin.max_deg || (bin.max_deg == 90.0 && a <= 90.0))) {
            s += (s.empty() ? "" : ", ") + std::string(names[ch]) + " " + fixed(a, 1) + "°";
        }
    }
    return s;
}

/// A table as rows of cells, the first row the header; written as Markdown or HTML.
using Table = std::vector<std::vector<std::string>>;

std::string markdown_cell(const std::string& s) {
    std::string out;
    for (const char c : s) {
        if (c == '|') out += "\\|";
        else out += c;
    }
    return out;
}

std::string markdown_table(const Table& t) {
    std::string s;
    for (std::size_t r = 0; r < t.size(); ++r) {
        s += "|";
        for (const std::string& cell : t[r]) {
            s += ' ';
            s += markdown_cell(cell);
            s += " |";
        }
        s += "\n";
        if (r == 0) {
            s += "|";
            for (std::size_t c = 0; c < t[r].size(); ++c) s += c == 0 ? "---|" : "---:|";
            s += "\n";
        }
    }
    return s;
}


std::string html_table(const Table& t) {
    std::string s = "<table>\n";
    for (std::size_t r = 0; r < t.size(); ++r) {
        s += "<tr>";
        for (const std::string& cell : t[r]) {
            s += r == 0 ? "<th>" + html_escape(cell) + "</th>" : "<td>" + html_escape(cell) + "</td>";
        }
        s += "</tr>\n";
    }
    return s + "</table>\n";
}

/// The content shared by both formats: a heading, paragraphs and tables, in order.
struct Document {
    std::string title;
    std::vector<std::pair<std::string, Table>> sections;  // (paragraph before, table)
    std::string note;
};

Document claims_document(const std::vector<ClipAnalysis>& analyses, const ColorSet& set, HueMeasure hue,
                         ClipMethod verdict_method) {
    Document d;
    if (analyses.empty()) throw Error("clip-claims: no method to report");
    const ClipClaimsSummary& first = analyses.front().summary;
    d.title = "Smits 1990, §4.3.4: the clip's claims measured";
    const std::array<double, 3> angles = face_angles_to_constant_y_deg(srgb());

    Table main{{"method", "clipped", "max |ΔL*|", "saturation lower", "|Δh_uv|° mean / p95 / max",
                "|Δh_ab|° mean / p95 / max", "|Δh_Oklab|° mean / p95 / max",
                "r(face angle, |Δh| " + hue_measure_label(hue) + ")"}};
    for (const ClipAnalysis& a : analyses) {
        const ClipClaimsSummary& s = a.summary;
        const double r = hue == HueMeasure::oklab ? s.correlation_oklab
                         : hue == HueMeasure::luv ? s.correlation_uv
                                                  : s.correlation_ab;
        main.push_back({std::string(clip_method_name(a.method)), std::to_string(s.clipped),
                        compact(std::max(s.max_abs_delta_l_ab, s.max_abs_delta_l_uv), 3),
                        percent(s.saturation_lower, s.clipped), stats_text(s.hue.uv), stats_text(s.hue.ab),
                        stats_text(s.hue.oklab), compact(r, 2)});
    }
    d.sections.emplace_back(
        "Set " + set.name + ": " + std::to_string(first.size) + " colours, " + std::to_string(first.clipped) +
            " out of the sRGB gamut (linear sRGB [0, 1]³). " + set.description +
            ". Every figure is over the clipped colours: |ΔL*| is CIELAB's and CIELUV's (the same "
            "function of Y), saturation is s_uv = C*uv / L*, hue changes are in degrees, r is "
            "Pearson's correlation (— when undefined: a constant |Δh|).",
        main);

    Table faces{{"method"}};
    std::vector<std::size_t> bins;
    for (std::size_t b = 0; b < first.angle_bins.size(); ++b) {
        bool used = false;
        for (const ClipAnalysis& a : analyses) used = used || a.summary.angle_bins[b].count > 0;
        if (!bin_faces(first.angle_bins[b], angles).empty() || used) {
            bins.push_back(b);
            const AngleBinHueStatistics& bin = first.angle_bins[b];
            faces[0].push_back(fixed(bin.min_deg, 0) + "–" + fixed(bin.max_deg, 0) + "° (" +
                               bin_faces(bin, angles) + "): n, mean / max |Δh|");
        }
    }
    for (const ClipAnalysis& a : analyses) {
        std::vector<std::string> row{std::string(clip_method_name(a.method))};
        for (const std::size_t b : bins) {
            const AngleBinHueStatistics& bin = a.summary.angle_bins[b];
            const ClipStatistics& s = hue_statistics_of(bin.hue, hue);
            row.push_back(bin.count == 0 ? "0" : std::to_string(bin.count) + ": " + compact(s.mean) + " / " + compact(s.max));
        }
        faces.push_back(row);
    }
    d.sections.emplace_back(
        "|Δh| of " + hue_measure_label(hue) + " in degrees by the angle between the face a colour was "
            "clipped onto and the plane of constant Y in XYZ (0° = parallel; both faces of a channel "
            "are parallel, so sRGB has three angles: r " + fixed(angles[0], 1) + "°, g " + fixed(angles[1], 1) +
            "°, b " + fixed(angles[2], 1) + "°).",
        faces);

    for (const ClipAnalysis& a : analyses) {
        if (a.method != verdict_method) continue;
        Table verdicts{{"claim (" + std::string(clip_method_name(verdict_method)) + ")", "holds", "measured"}};
        for (const ClaimVerdict& v : clip_claim_verdicts(a.summary, hue)) {
            verdicts.push_back({v.claim, v.holds ? "yes" : "no", v.verdict});
        }
        d.sections.emplace_back("Verdicts on the thesis' claims for its clip (" +
                                    std::string(clip_method_name(verdict_method)) + ") on this set.",
                                verdicts);
    }
    d.note = "The clip of every method is GamutClipper on sRGB (irid_gamut); smits-xyz is the thesis' XYZ "
             "form (GamutClipper::clip_xyz). Hue changes are undefined (left out) where the input has "
             "no hue (C*uv or C*ab ≤ 1, Oklab C ≤ 0.005) or the output is black or white.";
    return d;
}

}  // namespace

ColorSet clip_claims_set(std::string_view name) {
    const RgbSpace& destination = srgb();
    if (name == "all") {
        std::vector<ColorSet> sets;
        for (const ClipReportSet s : clip_report_sets()) sets.push_back(clip_report_color_set(s, destination));
        return union_color_set(sets);
    }
    const std::vector<ClipReportSet> one = parse_clip_report_sets(name);
    return clip_report_color_set(one.front(), destination);
}

std::vector<ClaimVerdict> clip_claim_verdicts(const ClipClaimsSummary& s, HueMeasure hue) {
    std::vector<ClaimVerdict> v;
    const double max_dl = std::max(s.max_abs_delta_l_ab, s.max_abs_delta_l_uv);
    v.push_back({"1. lightness is constant for every clipped colour", max_dl <= 1e-9,
                 "max |ΔL*| = " + compact(max_dl, 3) + " over " + std::to_string(s.clipped) +
                     " clipped colours (holds when ≤ 1e-9, rounding)"});
    const bool lower = s.saturation_lower == s.clipped;
    v.push_back({"2. saturation is lower", lower,
                 std::to_string(s.saturation_lower) + " of " + std::to_string(s.clipped) +
                     " lower (s_uv = C*uv / L*)" +
                     (lower ? std::string()
                            : "; " + std::to_string(s.saturation_equal) + " equal, " +
                                  std::to_string(s.saturation_higher) + " higher")});
    const bool small = s.hue.uv.count > 0 && s.hue.uv.max <= 1.0;
    v.push_back({"3. the hue change is small (the thesis' hue: CIELUV h_uv)", small,
                 "|Δh_uv| mean " + compact(s.hue.uv.mean) + "°, max " + compact(s.hue.uv.max) +
                     "° (holds when max ≤ 1°); in CIELAB mean " + compact(s.hue.ab.mean) + "°, max " +
                     compact(s.hue.ab.max) + "°; in Oklab mean " + compact(s.hue.oklab.mean) + "°, max " +
                     compact(s.hue.oklab.max) + "°"});

    // 4: the exception at faces nearly parallel to constant lightness.
    const double r = hue == HueMeasure::oklab ? s.correlation_oklab
                     : hue == HueMeasure::luv ? s.correlation_uv
                                              : s.correlation_ab;
    const AngleBinHueStatistics* nearest = nullptr;
    double largest_other = -1.0;
    for (const AngleBinHueStatistics& bin : s.angle_bins) {
        const ClipStatistics& st = hue_statistics_of(bin.hue, hue);
        if (st.count == 0) continue;
        if (nearest == nullptr) {
            nearest = &bin;
        } else {
            largest_other = std::max(largest_other, st.mean);
        }
    }
    std::string measured = "r(face angle, |Δh| " + hue_measure_label(hue) + ") = " + compact(r, 2);
    bool holds = false;
    if (nearest != nullptr) {
        const double near_mean = hue_statistics_of(nearest->hue, hue).mean;
        measured += "; faces nearest parallel reached (" + fixed(nearest->min_deg, 0) + "–" +
                    fixed(nearest->max_deg, 0) + "°): mean |Δh| " + compact(near_mean) + "°";
        if (largest_other >= 0.0) measured += ", largest mean of the other faces " + compact(largest_other) + "°";
        holds = !std::isnan(r) && r < -0.1 && near_mean > largest_other;
    }
    measured += " (holds when r < −0.1 and those faces have the largest mean)";
    v.push_back({"4. ... except where a face is nearly parallel to constant lightness (" + hue_measure_label(hue) + ")",
                 holds, measured});
    return v;
}

std::string clip_claims_markdown(const std::vector<ClipAnalysis>& analyses, const ColorSet& set, HueMeasure hue,
                                 ClipMethod verdict_method) {
    const Document d = claims_document(analyses, set, hue, verdict_method);
    std::string s = "# " + d.title + "\n\n";
    for (const auto& [paragraph, table] : d.sections) s += paragraph + "\n\n" + markdown_table(table) + "\n";
    return s + d.note + "\n";
}

std::string clip_claims_html(const std::vector<ClipAnalysis>& analyses, const ColorSet& set, HueMeasure hue,
                             ClipMethod verdict_method) {
    const Document d = claims_document(analyses, set, hue, verdict_method);
    std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                    html_escape(d.title) +
                    "</title>\n<style>body{font-family:sans-serif;max-width:72em;margin:1em auto}"
                    "table{border-collapse:collapse;margin:0.5em 0 1.5em}th,td{border:1px solid #ccc;"
                    "padding:0.25em 0.5em;text-align:right}th:first-child,td:first-child{text-align:left}"
                    "</style>\n</head>\n<body>\n<h1>" +
                    html_escape(d.title) + "</h1>\n";
    for (const auto& [paragraph, table] : d.sections) s += "<p>" + html_escape(paragraph) + "</p>\n" + html_table(table);
    return s + "<p>" + html_escape(d.note) + "</p>\n</body>\n</html>\n";
}

FigureResult draw_clip_claims(const FigureRequest& request) {
    const Options options(request, {"set", "hue"});
    const std::string set_name = options.choice("set", {"spectrum", "interference", "rec2020", "all"}, "spectrum");
    const std::string hue_name = options.choice("hue", {"oklab", "lab", "luv"}, "oklab");
    const HueMeasure hue = parse_hue_measure(hue_name);
    const ColorSet set = clip_claims_set(set_name);

    std::vector<ClipAnalysis> analyses;
    for (const ClipMethod m : clip_methods()) analyses.push_back(analyse_clip(set, Gamut(srgb()), m));

    const bool html = lower_extension(request.output) == ".html";
    const std::string text = html ? clip_claims_html(analyses, set, hue, ClipMethod::smits)
                                  : clip_claims_markdown(analyses, set, hue, ClipMethod::smits);
    io::write_output_file(request.output, text);

    FigureResult result;
    for (const ClipAnalysis& a : analyses) {
        if (a.method != ClipMethod::smits) continue;
        for (const ClaimVerdict& v : clip_claim_verdicts(a.summary, hue)) {
            result.measurements.emplace_back(v.claim, std::string(v.holds ? "holds" : "does not hold") + ": " + v.verdict);
        }
    }
    result.caption = "The claims of Smits 1990, §4.3.4 for the constant-lightness clip, measured on the " +
                     set_name + " set clipped into linear sRGB by every method (clip analysis of irid_gamut): "
                     "max |ΔL*|, the share of clipped colours whose saturation s_uv fell, |Δh| in CIELUV, "
                     "CIELAB and Oklab, and |Δh| (" + hue_measure_label(hue) +
                     ") by the angle between the face reached and the plane of constant Y, with a verdict "
                     "per claim for smits. Options: set=" + set_name + ", hue=" + hue_name + ".";
    return result;
}

}  // namespace irid::figures::detail
