// Table 1 of Smits 1990: the operations the RGB clip needs per colour, counted by running the
// library's clip (smits_clip_rgb) on a counting number type, beside the thesis' numbers.

#include <irid/gamut/clip.h>
#include <irid/io/output_file.h>

#include "figure_data.h"
#include "figure_support.h"

#include <algorithm>
#include <array>
#include <vector>

namespace irid::figures::detail {

namespace {

std::string range_text(const CountRange& r) {
    return r.lo == r.hi ? std::to_string(r.lo)
                        : std::to_string(r.lo) + "–" + std::to_string(r.hi);
}

struct Row {
    const char* name;
    const OperationCounts* counts;
};

std::array<Row, 4> rows_of(const Table1& t) {
    return {{{"in gamut", &t.in_gamut},
             {"1 plane crossed", &t.one_plane},
             {"2 planes crossed", &t.two_planes},
             {"3 planes crossed", &t.three_planes}}};
}

/// "9" or "9 (thesis 5–7)" when outside the thesis' range. The in-gamut row is compared with
/// nothing: the thesis counts clipped colours.
std::string cell(long ours, const CountRange& thesis, bool clipped) {
    if (!clipped || thesis.contains(ours)) return std::to_string(ours);
    return std::to_string(ours) + " (outside " + range_text(thesis) + ")";
}

/// How the clipped rows compare with one thesis range: "within 9–11", or "9–12, above the
/// thesis' 9–11 by up to 1".
std::string comparison(const Table1& t, long OperationCounts::*op, const CountRange& thesis) {
    long lo = t.one_plane.*op, hi = lo;
    for (const OperationCounts* c : {&t.two_planes, &t.three_planes}) {
        lo = std::min(lo, c->*op);
        hi = std::max(hi, c->*op);
    }
    const CountRange ours{lo, hi};
    if (lo >= thesis.lo && hi <= thesis.hi) {
        return range_text(ours) + ", within the thesis' " + range_text(thesis);
    }
    std::string out = range_text(ours) + " against the thesis' " + range_text(thesis);
    if (hi > thesis.hi) out += ", above it by up to " + std::to_string(hi - thesis.hi);
    if (lo < thesis.lo) out += ", below it by up to " + std::to_string(thesis.lo - lo);
    return out;
}

/// The notes under the table (plain text; the same words in both formats), from the counts.
std::vector<std::string> notes(const Table1& t) {
    std::vector<std::string> out{
        "Counted, not estimated: the library's smits_clip_rgb template (include/irid/gamut/"
        "clip.h) runs on a number type that counts each comparison, addition or subtraction, "
        "multiplication and division, for an sRGB colour inside the gamut and for colours "
        "crossing one, two and three of the cube's planes.",
        "Per clipped colour: comparisons " +
            comparison(t, &OperationCounts::comparisons, thesis_comparisons) + "; additions " +
            comparison(t, &OperationCounts::additions, thesis_additions) +
            "; multiplications " +
            comparison(t, &OperationCounts::multiplications, thesis_multiplications) +
            "; divisions " + comparison(t, &OperationCounts::divisions, thesis_divisions) + "."};
    if (t.one_plane.comparisons > thesis_comparisons.hi) {
        out.push_back(
            "The extra comparisons are tests the thesis' count does not include: the two cases "
            "it leaves open (luminance at or below 0, the grey at or above the white) and, per "
            "crossed plane, the comparison that keeps the largest intersection parameter.");
    }
    return out;
}


}  // namespace

std::string table1_markdown(const Table1& t) {
    std::string out =
        "## Table 1: operations per colour of the RGB clip (Smits 1990, §4.3)\n\n"
        "| colour | comparisons | additions | multiplications | divisions |\n"
        "| --- | --- | --- | --- | --- |\n";
    for (const Row& r : rows_of(t)) {
        const bool clipped = r.counts != &t.in_gamut;
        out += "| " + std::string(r.name) + " | " +
               cell(r.counts->comparisons, thesis_comparisons, clipped) + " | " +
               cell(r.counts->additions, thesis_additions, clipped) + " | " +
               cell(r.counts->multiplications, thesis_multiplications, clipped) + " | " +
               cell(r.counts->divisions, thesis_divisions, clipped) + " |\n";
    }
    out += "| thesis, Table 1 (per clipped colour) | " + range_text(thesis_comparisons) + " | " +
           range_text(thesis_additions) + " | " + range_text(thesis_multiplications) + " | " +
           range_text(thesis_divisions) + " |\n\n";
    for (const std::string& n : notes(t)) out += "- " + n + "\n";
    return out;
}

std::string table1_html(const Table1& t, bool page) {
    std::string body =
        "<section class=\"irid-table1\">\n"
        "<h2>Table 1: operations per colour of the RGB clip (Smits 1990, §4.3)</h2>\n"
        "<table>\n<thead><tr><th>colour</th><th>comparisons</th><th>additions</th>"
        "<th>multiplications</th><th>divisions</th></tr></thead>\n<tbody>\n";
    for (const Row& r : rows_of(t)) {
        const bool clipped = r.counts != &t.in_gamut;
        body += "<tr><td>" + html_escape(r.name) + "</td><td>" +
                html_escape(cell(r.counts->comparisons, thesis_comparisons, clipped)) +
                "</td><td>" + html_escape(cell(r.counts->additions, thesis_additions, clipped)) +
                "</td><td>" +
                html_escape(cell(r.counts->multiplications, thesis_multiplications, clipped)) +
                "</td><td>" + html_escape(cell(r.counts->divisions, thesis_divisions, clipped)) +
                "</td></tr>\n";
    }
    body += "<tr class=\"thesis\"><td>thesis, Table 1 (per clipped colour)</td><td>" +
            html_escape(range_text(thesis_comparisons)) + "</td><td>" +
            html_escape(range_text(thesis_additions)) + "</td><td>" +
            html_escape(range_text(thesis_multiplications)) + "</td><td>" +
            html_escape(range_text(thesis_divisions)) + "</td></tr>\n</tbody>\n</table>\n<ul>\n";
    for (const std::string& n : notes(t)) body += "<li>" + html_escape(n) + "</li>\n";
    body += "</ul>\n</section>\n";
    if (!page) return body;
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<title>irid: Table 1 of Smits 1990</title>\n<style>\n"
           "body { font-family: sans-serif; max-width: 60em; margin: 2em auto; }\n"
           "table { border-collapse: collapse; }\n"
           "th, td { border: 1px solid #bbb; padding: 0.3em 0.7em; text-align: right; }\n"
           "th:first-child, td:first-child { text-align: left; }\n"
           "tr.thesis { background: #f2f2f2; }\n"
           "</style>\n</head>\n<body>\n" +
           body + "</body>\n</html>\n";
}

FigureResult draw_table1(const FigureRequest& request) {
    const Options options(request, {"html"});
    const bool page = options.choice("html", {"page", "fragment"}, "page") == "page";
    const Table1 counts = count_smits_operations();
    const bool markdown = lower_extension(request.output) == ".md";
    io::write_output_file(request.output,
                                   markdown ? table1_markdown(counts) : table1_html(counts, page));

    FigureResult result;
    for (const Row& r : rows_of(counts)) {
        result.measurements.emplace_back(
            r.name, std::to_string(r.counts->comparisons) + " comparisons, " +
                        std::to_string(r.counts->additions) + " additions, " +
                        std::to_string(r.counts->multiplications) + " multiplications, " +
                        std::to_string(r.counts->divisions) + " divisions");
    }
    result.measurements.emplace_back(
        "thesis (per clipped colour)",
        range_text(thesis_comparisons) + " comparisons, " + range_text(thesis_additions) +
            " additions, " + range_text(thesis_multiplications) + " multiplications, " +
            range_text(thesis_divisions) + " divisions");
    result.caption =
        "Table 1 of Smits 1990: the operations the thesis' RGB clip needs per colour, counted "
        "by running irid's clip on a counting number type (sRGB; a colour in the gamut and "
        "colours crossing one, two and three planes), beside the thesis' numbers (5–7 "
        "comparisons, 9–11 additions, 7 multiplications, 1–3 divisions). Written as " +
        std::string(markdown ? "Markdown" : (page ? "an HTML page" : "an HTML fragment")) +
        ". Options: html=" + (page ? "page" : "fragment") + ".";
    return result;
}

}  // namespace irid::figures::detail
