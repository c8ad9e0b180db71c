// ICC profiles through Little CMS 2, and OpenEXR chromaticities (irid/exchange/icc.h).
#include <irid/color/adaptation.h>
#include <irid/color/numeric_table.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/exchange/icc.h>
#include <irid/parallel.h>

#include "png_space.h"

#include <fmt/core.h>
#include <lcms2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cwchar>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace irid {
namespace {

/// An lcms2 context that keeps the first error lcms2 reports (lcms2's own words, which name the
/// tag or the structure it could not read).
struct Context {
    cmsContext handle = nullptr;
    std::string error;

    Context() {
        handle = cmsCreateContext(nullptr, this);
        if (handle == nullptr) throw Error("Little CMS could not create a context");
        cmsSetLogErrorHandlerTHR(handle, [](cmsContext c, cmsUInt32Number, const char* text) {
            auto* self = static_cast<Context*>(cmsGetContextUserData(c));
            if (self != nullptr && self->error.empty() && text != nullptr) self->error = text;
        });
    }
    ~Context() { cmsDeleteContext(handle); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    /// lcms2's reason, or `fallback`.
    [[nodiscard]] std::string reason(const char* fallback) const { return error.empty() ? fallback : error; }
};

struct ProfileCloser {
    void operator()(void* p) const noexcept { cmsCloseProfile(p); }
};
using Profile = std::unique_ptr<void, ProfileCloser>;
struct CurveFree {
    void operator()(cmsToneCurve* c) const noexcept { cmsFreeToneCurve(c); }
};
using Curve = std::unique_ptr<cmsToneCurve, CurveFree>;
struct MluFree {
    void operator()(cmsMLU* m) const noexcept { cmsMLUfree(m); }
};
using Mlu = std::unique_ptr<cmsMLU, MluFree>;

/// ICC.1:2022 §7.2.4 (the PCS illuminant, D50), as lcms2 encodes it.
Xyz d50() noexcept {
    const cmsCIEXYZ* w = cmsD50_XYZ();
    return {w->X, w->Y, w->Z};
}

Xy chromaticity(const Xyz& c, const std::string& where, const char* what) {
    const double sum = c.X + c.Y + c.Z;
    if (!(std::isfinite(sum) && sum > 0.0)) {
        throw Error(where + "the " + what + " (" + format_shortest(c.X) + ", " + format_shortest(c.Y) +
                    ", " + format_shortest(c.Z) + ") has no chromaticity");
    }
    return {c.X / sum, c.Y / sum};
}

Xyz times(const Mat3& m, const Xyz& c) noexcept {
    const Vec3 v = m * Vec3{c.X, c.Y, c.Z};
    return {v[0], v[1], v[2]};
}

/// A signature as its four characters ("CMYK", "GRAY").
std::string signature_text(std::uint32_t sig) {
    std::string s;
    for (int shift = 24; shift >= 0; shift -= 8) {
        const char ch = static_cast<char>((sig >> shift) & 0xFF);
        s += (ch >= 32 && ch < 127) ? ch : '?';
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

std::string data_space_name(std::uint32_t cs) {
    switch (cs) {
        case cmsSigCmykData: return "CMYK";
        case cmsSigCmyData: return "CMY";
        case cmsSigGrayData: return "greyscale";
        case cmsSigLabData: return "CIELAB";
        case cmsSigXYZData: return "CIE XYZ";
        case cmsSigYCbCrData: return "YCbCr";
        case cmsSigHsvData: return "HSV";
        case cmsSigHlsData: return "HLS";
        default: return "'" + signature_text(cs) + "' data";
    }
}

/// A tone curve as a TransferFunction. Throws irid::Error (after `where`) for a curve that is
/// no decoding (one that falls, is flat, or has parameters out of range): lcms2 would apply it
/// as it is (a reversed table inverts the image), which is never what an image means.
TransferFunction transfer_of(const cmsToneCurve* c, const std::string& where, const char* channel) {
    // lcms2's types 1-5 are ICC.1's parametric function types 0-4.
    const cmsInt32Number type = cmsGetToneCurveParametricType(c);
    try {
        if (type >= 1 && type <= 5) {
            const std::size_t count = TransferFunction::parametric_counts[static_cast<std::size_t>(type - 1)];
            return TransferFunction::parametric(type - 1, std::span<const double>(cmsGetToneCurveParams(c), count));
        }
        const cmsUInt32Number n = cmsGetToneCurveEstimatedTableEntries(c);
        const cmsUInt16Number* table = cmsGetToneCurveEstimatedTable(c);
        if (table == nullptr || n < 2) throw Error("a tone curve without a table");
        std::vector<double> linear(n);
        for (cmsUInt32Number i = 0; i < n; ++i) linear[i] = table[i] / 65535.0;
        return TransferFunction::sampled(std::move(linear));
    } catch (const Error& e) {
        throw Error(where + "its " + channel + " tone curve is no decoding of image values: " + e.what());
    }
}

bool same_curve(const TransferFunction& a, const TransferFunction& b) {
    if (a.kind() != b.kind()) return false;
    if (a.kind() == TransferFunction::Kind::sampled) {
        const auto x = a.samples(), y = b.samples();
        return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin());
    }
    return a.parameters() == b.parameters();
}

/// The exact space of a matrix/TRC profile (see icc.h), or nothing with the reason (three
/// different curves). Throws irid::Error for tags that cannot be read or used.
std::optional<RgbSpace> matrix_trc_space(cmsHPROFILE h, const std::string& name, const std::string& where,
                                         const Context& ctx, std::string& reason) {
    const auto* r = static_cast<const cmsCIEXYZ*>(cmsReadTag(h, cmsSigRedColorantTag));
    const auto* g = static_cast<const cmsCIEXYZ*>(cmsReadTag(h, cmsSigGreenColorantTag));
    const auto* b = static_cast<const cmsCIEXYZ*>(cmsReadTag(h, cmsSigBlueColorantTag));
    const auto* rt = static_cast<const cmsToneCurve*>(cmsReadTag(h, cmsSigRedTRCTag));
    const auto* gt = static_cast<const cmsToneCurve*>(cmsReadTag(h, cmsSigGreenTRCTag));
    const auto* bt = static_cast<const cmsToneCurve*>(cmsReadTag(h, cmsSigBlueTRCTag));
    if (r == nullptr || g == nullptr || b == nullptr || rt == nullptr || gt == nullptr || bt == nullptr) {
        throw Error(where + "its colorant or tone-curve tags cannot be read: " +
                    ctx.reason("a tag is damaged"));
    }
    const TransferFunction curves[3] = {transfer_of(rt, where, "red"), transfer_of(gt, where, "green"),
                                        transfer_of(bt, where, "blue")};
    if (!same_curve(curves[0], curves[1]) || !same_curve(curves[0], curves[2])) {
        reason = "three different tone curves";
        return std::nullopt;
    }

    // Back from the PCS's D50 to the profile's own white.
    Mat3 to_native = Mat3::identity();
    Xyz white = d50();
    // lcms2 reads the chad tag (an s15Fixed16ArrayType of 9) as 9 doubles, row by row.
    if (const auto* chad = static_cast<const double*>(cmsReadTag(h, cmsSigChromaticAdaptationTag))) {
        Mat3 m;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) m[i][static_cast<std::size_t>(j)] = chad[i * 3 + j];
        }
        try {
            to_native = inverse(m, "chromatic adaptation (chad) matrix");
        } catch (const Error& e) {
            throw Error(where + e.what());
        }
        white = times(to_native, d50());
    } else if (const auto* wtpt = static_cast<const cmsCIEXYZ*>(cmsReadTag(h, cmsSigMediaWhitePointTag))) {
        // Version 2: colorants adapted to D50 by Bradford from the media white (ICC.1:2001 §6.3).
        const Xyz w{wtpt->X, wtpt->Y, wtpt->Z};
        const Xyz pcs = d50();
        if (std::abs(w.X - pcs.X) > 1e-4 || std::abs(w.Y - pcs.Y) > 1e-4 || std::abs(w.Z - pcs.Z) > 1e-4) {
            try {
                to_native = adaptation_matrix(pcs, w, ChromaticAdaptation::bradford);
            } catch (const Error& e) {
                throw Error(where + "media white point: " + e.what());
            }
            white = w;
        }
    }
    const Xy rxy = chromaticity(times(to_native, {r->X, r->Y, r->Z}), where, "red colorant");
    const Xy gxy = chromaticity(times(to_native, {g->X, g->Y, g->Z}), where, "green colorant");
    const Xy bxy = chromaticity(times(to_native, {b->X, b->Y, b->Z}), where, "blue colorant");
    const Xy wxy = chromaticity(white, where, "white point");
    try {
        return RgbSpace(name, {rxy, gxy, bxy}, wxy, curves[0]);
    } catch (const Error& e) {
        throw Error(where + "its colorants make no RGB space: " + e.what());
    }
}

/// UTF-8 → the UTF-16 units lcms2 stores, one per wchar_t; malformed bytes and characters beyond
/// U+FFFF become U+FFFD.
std::wstring wide(std::string_view s) {
    std::wstring out;
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
        if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size()) {
            out += L'\uFFFD';
            ++i;
            continue;
        }
        std::uint32_t code = extra == 0 ? c : (c & (0x3Fu >> extra));
        bool ok = true;
        for (int k = 1; k <= extra; ++k) {
            const auto n = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
            ok = ok && (n >> 6) == 2;
            code = (code << 6) | (n & 0x3Fu);
        }
        // Beyond the Basic Multilingual Plane too: lcms2 2.14 writes each wchar_t as one UTF-16
        // unit, and its surrogate pairs do not read back reliably.
        if (!ok || code > 0xFFFF || (code >= 0xD800 && code <= 0xDFFF)) code = 0xFFFD;
        out += static_cast<wchar_t>(code);
        i += ok ? static_cast<std::size_t>(extra) + 1 : 1;
    }
    return out;
}

/// lcms2's wchar_t text (UTF-16 units from the profile's mluc, or whole code points) → UTF-8;
/// what is not a Unicode scalar value becomes U+FFFD.
std::string utf8(std::wstring_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        auto c = static_cast<std::uint32_t>(s[i]);
        if (c >= 0xD800 && c <= 0xDBFF && i + 1 < s.size()) {
            const auto low = static_cast<std::uint32_t>(s[i + 1]);
            if (low >= 0xDC00 && low <= 0xDFFF) {
                c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
                ++i;
            }
        }
        if (c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = 0xFFFD;
        if (c < 0x80) {
            out += static_cast<char>(c);
        } else if (c < 0x800) {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        } else if (c < 0x10000) {
            out += static_cast<char>(0xE0 | (c >> 12));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (c >> 18));
            out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }
    return out;
}

}  // namespace

/// lcms2's transform to the PCS (XYZ D50) and the context it lives in.
struct IccProfile::Transform {
    Context context;
    cmsHTRANSFORM handle = nullptr;
    ~Transform() {
        if (handle != nullptr) cmsDeleteTransform(handle);
    }
};

IccProfile IccProfile::parse(std::span<const unsigned char> bytes, const std::string& what) {
    const std::string where = what + ": ICC profile: ";
    // ICC.1:2022 §7.2 and §7.3: a 128-byte header, then the tag count.
    if (bytes.size() < 132) {
        throw Error(where + "only " + std::to_string(bytes.size()) +
                    " bytes; a profile holds a 128-byte header and a tag table");
    }
    if (bytes.size() > (std::size_t{1} << 30)) throw Error(where + "larger than 1 GiB");
    // ICC.1:2022 §7.2.2: the profile's size, big-endian, in its first four bytes.
    const std::uint64_t declared = (std::uint64_t{bytes[0]} << 24) | (std::uint64_t{bytes[1]} << 16) |
                                   (std::uint64_t{bytes[2]} << 8) | std::uint64_t{bytes[3]};
    if (declared > bytes.size()) {
        throw Error(where + "truncated: its header declares " + std::to_string(declared) + " bytes and " +
                    std::to_string(bytes.size()) + " are there");
    }
    auto transform = std::make_shared<Transform>();
    Context& ctx = transform->context;
    const Profile h(cmsOpenProfileFromMemTHR(ctx.handle, bytes.data(), static_cast<cmsUInt32Number>(bytes.size())));
    if (!h) throw Error(where + "cannot be read: " + ctx.reason("not a valid ICC profile"));

    // Signatures as numbers: a profile may hold any four bytes, which as lcms2's enum types would
    // be values outside them.
    const auto cls = static_cast<std::uint32_t>(cmsGetDeviceClass(h.get()));
    if (cls == cmsSigLinkClass) {
        throw Error(where + "a device link (it converts between two devices' values and defines no "
                            "colour space of its own); an image needs an input, display or colour-space profile");
    }
    if (cls == cmsSigAbstractClass) {
        throw Error(where + "an abstract profile (an edit of colours in the connection space), not "
                            "the colour space of an image");
    }
    if (cls == cmsSigNamedColorClass) {
        throw Error(where + "a named-colour profile (a palette of named colours), not the colour space "
                            "of an image");
    }
    const auto data = static_cast<std::uint32_t>(cmsGetColorSpace(h.get()));
    if (data != cmsSigRgbData) {
        throw Error(where + "a " + data_space_name(data) + " profile; irid reads RGB images, whose "
                            "profiles have RGB data");
    }
    const auto pcs = static_cast<std::uint32_t>(cmsGetPCS(h.get()));
    if (pcs != cmsSigXYZData && pcs != cmsSigLabData) {
        throw Error(where + "its connection space is '" + signature_text(pcs) + "'; ICC.1 allows XYZ or Lab");
    }

    IccProfile out;
    // The description in English where the profile has it (lcms2 falls back to its first).
    const cmsUInt32Number size = cmsGetProfileInfo(h.get(), cmsInfoDescription, "en", "US", nullptr, 0);
    if (size > sizeof(wchar_t)) {
        std::wstring text(size / sizeof(wchar_t), L'\0');
        cmsGetProfileInfo(h.get(), cmsInfoDescription, "en", "US", text.data(), size);
        text.resize(std::wcslen(text.c_str()));
        out.m_description = utf8(text);
    }
    const cmsUInt32Number v = cmsGetEncodedICCversion(h.get());
    out.m_version = fmt::format("{}.{}", (v >> 24) & 0xFF, (v >> 20) & 0xF);

    // An A2B table takes precedence over the matrix/TRC tags (ICC.1:2022 §8.4; lcms2 and every
    // CMM use it): a profile with both (DisplayCAL's "XYZ LUT + matrix") is a LUT profile.
    const bool a2b = cmsIsTag(h.get(), cmsSigAToB0Tag) || cmsIsTag(h.get(), cmsSigAToB1Tag);
    if (a2b) {
        out.m_not_exact = "a LUT-based profile";
    } else if (cmsIsMatrixShaper(h.get())) {
        const std::string name = out.m_description.empty() ? "icc-profile" : out.m_description;
        out.m_space = matrix_trc_space(h.get(), name, where, ctx, out.m_not_exact);
    }
    if (!a2b && !cmsIsMatrixShaper(h.get())) {
        throw Error(where + "it has neither matrix/TRC tags nor an A2B table: nothing turns its "
                            "values into colours" +
                    (ctx.error.empty() ? std::string() : " (" + ctx.error + ")"));
    }
    // Relative colorimetric always: lcms2 takes A2B1 for it, else A2B0, without the black-point
    // compensation it adds to the perceptual intent of version 4 profiles.
    const cmsUInt32Number intent = INTENT_RELATIVE_COLORIMETRIC;
    const Profile xyz(cmsCreateXYZProfileTHR(ctx.handle));
    if (!xyz) throw Error(where + "Little CMS could not create an XYZ profile");
    transform->handle = cmsCreateTransformTHR(ctx.handle, h.get(), TYPE_RGB_FLT, xyz.get(), TYPE_XYZ_FLT,
                                              intent, cmsFLAGS_NOCACHE | cmsFLAGS_NOOPTIMIZE);
    if (transform->handle == nullptr) {
        throw Error(where + "Little CMS cannot use it: " + ctx.reason("its tags are damaged"));
    }
    out.m_transform = std::move(transform);
    return out;
}

void IccProfile::to_xyz(std::span<const float> in, std::span<float> out, const Xy& white, int threads) const {
    if (in.size() % 3 != 0 || in.size() != out.size()) {
        throw Error("IccProfile::to_xyz: " + std::to_string(in.size()) + " values in and " +
                    std::to_string(out.size()) + " out; both must be the same number of whole triples");
    }
    // lcms2's float XYZ is relative to the PCS white D50 at Y = 1.
    const Mat3 adapt = adaptation_matrix(d50(), xy_to_xyz(white), ChromaticAdaptation::bradford);
    const cmsHTRANSFORM handle = m_transform->handle;
    constexpr std::size_t chunk = 4096;
    parallel_ranges(
        in.size() / 3, threads,
        [&](std::size_t begin, std::size_t end) {
            std::vector<float> source(chunk * 3), xyz(chunk * 3);
            for (std::size_t at = begin; at < end; at += chunk) {
                const std::size_t n = std::min(chunk, end - at);
                std::copy_n(in.data() + at * 3, n * 3, source.data());
                cmsDoTransform(handle, source.data(), xyz.data(), static_cast<cmsUInt32Number>(n));
                for (std::size_t i = 0; i < n; ++i) {
                    const Xyz c = times(adapt, {xyz[i * 3], xyz[i * 3 + 1], xyz[i * 3 + 2]});
                    out[(at + i) * 3] = static_cast<float>(c.X);
                    out[(at + i) * 3 + 1] = static_cast<float>(c.Y);
                    out[(at + i) * 3 + 2] = static_cast<float>(c.Z);
                }
            }
        },
        chunk);
}

std::string IccProfile::summary() const {
    return fmt::format("the ICC profile '{}' (version {}, {})", m_description, m_version,
                       m_space ? "matrix/TRC" : m_not_exact + ", through Little CMS");
}

bool icc_curve_can_hold(const TransferFunction& t) noexcept { return t.decode(1.0) <= 1.0 + 1e-9; }

std::vector<unsigned char> make_icc_profile(const RgbSpace& space, std::string_view description) {
    const TransferFunction& t = space.transfer();
    if (!icc_curve_can_hold(t)) {
        throw Error("ICC profile of " + space.name() + ": its curve decodes the code value 1 to " +
                    format_shortest(t.decode(1.0)) +
                    " (PQ: absolute luminance up to 10000 cd/m²; HLG: 1000 cd/m², through an OOTF on "
                    "luminance; ACEScct: scene light up to 222.86), which an ICC.1 tone curve (relative, 0 to 1, "
                    "per channel) cannot hold");
    }
    Context ctx;
    Curve curve;
    if (const auto p = t.parameters()) {
        const auto& q = *p;
        if (q[1] == 1.0 && q[2] == 0.0 && q[3] == 0.0 && q[4] == 0.0 && q[5] == 0.0 && q[6] == 0.0) {
            const double g[] = {q[0]};  // ICC function type 0 (lcms2's 1): a power law
            curve.reset(cmsBuildParametricToneCurve(ctx.handle, 1, g));
        } else if (q[5] == 0.0 && q[6] == 0.0) {
            const double g[] = {q[0], q[1], q[2], q[3], q[4]};  // ICC type 3 (lcms2's 4)
            curve.reset(cmsBuildParametricToneCurve(ctx.handle, 4, g));
        } else {
            curve.reset(cmsBuildParametricToneCurve(ctx.handle, 5, q.data()));  // ICC type 4
        }
    } else {
        const std::span<const double> s = t.samples();
        std::vector<float> table(s.begin(), s.end());
        curve.reset(cmsBuildTabulatedToneCurveFloat(ctx.handle, static_cast<cmsUInt32Number>(table.size()),
                                                    table.data()));
    }
    if (!curve) throw Error("ICC profile of " + space.name() + ": " + ctx.reason("the tone curve failed"));

    const cmsCIExyY white{space.white().x, space.white().y, 1.0};
    const RgbPrimaries& p = space.primaries();
    const cmsCIExyYTRIPLE primaries{{p.red.x, p.red.y, 1.0}, {p.green.x, p.green.y, 1.0}, {p.blue.x, p.blue.y, 1.0}};
    cmsToneCurve* curves[3] = {curve.get(), curve.get(), curve.get()};
    const Profile h(cmsCreateRGBProfileTHR(ctx.handle, &white, &primaries, curves));
    if (!h) throw Error("ICC profile of " + space.name() + ": " + ctx.reason("Little CMS refused the space"));
    cmsSetProfileVersion(h.get(), 4.3);
    cmsSetDeviceClass(h.get(), cmsSigDisplayClass);

    const std::string text = description.empty() ? space.name() + " (irid)" : std::string(description);
    const Mlu desc(cmsMLUalloc(ctx.handle, 1));
    const Mlu copyright(cmsMLUalloc(ctx.handle, 1));
    const std::wstring wide_text = wide(text);
    if (!desc || !copyright || !cmsMLUsetWide(desc.get(), "en", "US", wide_text.c_str()) ||
        !cmsMLUsetWide(copyright.get(), "en", "US", L"No copyright, use freely") ||
        !cmsWriteTag(h.get(), cmsSigProfileDescriptionTag, desc.get()) ||
        !cmsWriteTag(h.get(), cmsSigCopyrightTag, copyright.get())) {
        throw Error("ICC profile of " + space.name() + ": " + ctx.reason("the text tags failed"));
    }
    const auto saved = [&](cmsHPROFILE profile) {
        cmsUInt32Number n = 0;
        if (!cmsSaveProfileToMem(profile, nullptr, &n) || n == 0) {
            throw Error("ICC profile of " + space.name() + ": " + ctx.reason("saving failed"));
        }
        std::vector<unsigned char> out(n);
        if (!cmsSaveProfileToMem(profile, out.data(), &n)) {
            throw Error("ICC profile of " + space.name() + ": " + ctx.reason("saving failed"));
        }
        out.resize(n);
        return out;
    };
    // lcms2 stamps the header with the time of creation (ICC.1 §7.2.8), so that the same space
    // would give different bytes, and different files, at every run. The date is fixed instead
    // (2026-01-01 00:00:00), read back, and the profile ID (an MD5 of the whole, §7.2.18)
    // computed over the result.
    std::vector<unsigned char> bytes = saved(h.get());
    static constexpr unsigned char date[12] = {0x07, 0xEA, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0};
    std::copy(std::begin(date), std::end(date), bytes.begin() + 24);
    const Profile fixed(cmsOpenProfileFromMemTHR(ctx.handle, bytes.data(), static_cast<cmsUInt32Number>(bytes.size())));
    if (!fixed || !cmsMD5computeID(fixed.get())) {
        throw Error("ICC profile of " + space.name() + ": " + ctx.reason("MD5 failed"));
    }
    bytes = saved(fixed.get());
    // What a reader will take from it: the same space, or an error (colorants beyond what
    // s15Fixed16Number can hold, a curve a 16-bit table cannot).
    const IccProfile back = IccProfile::parse(bytes, "the ICC profile of " + space.name());
    const auto near = [](const Xy& a, const Xy& b) {
        return std::abs(a.x - b.x) <= 1e-4 && std::abs(a.y - b.y) <= 1e-4;
    };
    const RgbSpace* r = back.rgb_space() ? &*back.rgb_space() : nullptr;
    if (r == nullptr || !near(r->primaries().red, p.red) || !near(r->primaries().green, p.green) ||
        !near(r->primaries().blue, p.blue) || !near(r->white(), space.white()) ||
        !(r->transfer().max_difference(t) <= 1e-4)) {
        throw Error("ICC profile of " + space.name() +
                    ": an ICC profile cannot hold this space (its colorants or its curve do not "
                    "read back within 1e-4)");
    }
    return bytes;
}

RgbSpace rgb_space_from_chromaticities(std::span<const float> c, const std::string& name, const std::string& what) {
    if (c.size() != 8) {
        throw Error(what + ": chromaticities: " + std::to_string(c.size()) +
                    " values; they are 8 (red, green, blue and white x, y)");
    }
    for (const float v : c) {
        if (!std::isfinite(v)) throw Error(what + ": chromaticities: a value is not finite");
    }
    // Primaries of real encodings lie within [-1, 2] (the widest camera gamuts reach y = 1.32
    // and -0.12, DaVinci Wide Gamut); a white is a real colour, inside the triangle x, y > 0,
    // x + y < 1.
    static constexpr const char* names[] = {"red", "green", "blue"};
    for (std::size_t i = 0; i < 6; ++i) {
        if (c[i] < -1.0f || c[i] > 2.0f) {
            throw Error(what + ": chromaticities: " + names[i / 2] + " " + (i % 2 == 0 ? "x" : "y") + " = " +
                        fmt::format("{}", c[i]) + "; primaries lie within [-1, 2]");
        }
    }
    if (!(c[6] > 0.0f && c[7] > 0.0f && c[6] + c[7] < 1.0f)) {
        throw Error(what + ": chromaticities: white (" + fmt::format("{}, {}", c[6], c[7]) +
                    ") is not a real colour (x > 0, y > 0, x + y < 1)");
    }
    const auto at = [&](std::size_t i) { return Xy{double{c[i]}, double{c[i + 1]}}; };
    try {
        return RgbSpace(name, {at(0), at(2), at(4)}, at(6), TransferFunction(TransferFunction::Kind::linear));
    } catch (const Error& e) {
        throw Error(what + ": chromaticities: " + e.what());
    }
}

std::array<float, 8> exr_chromaticities(const RgbSpace& s) noexcept {
    const RgbPrimaries& p = s.primaries();
    const auto f = [](double v) { return static_cast<float>(v); };
    return {f(p.red.x),  f(p.red.y),  f(p.green.x),   f(p.green.y),
            f(p.blue.x), f(p.blue.y), f(s.white().x), f(s.white().y)};
}

const RgbSpace* matching_builtin_space(const RgbSpace& space, double tolerance, bool ignore_curve) noexcept {
    const auto near = [tolerance](const Xy& a, const Xy& b) {
        return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance;
    };
    for (const RgbSpace* b : builtin_rgb_spaces()) {
        const RgbPrimaries& p = space.primaries();
        const RgbPrimaries& q = b->primaries();
        if (!near(p.red, q.red) || !near(p.green, q.green) || !near(p.blue, q.blue) ||
            !near(space.white(), b->white())) {
            continue;
        }
        if (ignore_curve || space.transfer().max_difference(b->transfer()) <= tolerance) return b;
    }
    return nullptr;
}

void check_tags_agree(const io::Image& image, const RgbSpace& space, const std::string& name) {
    const auto near = [](const Xy& a, const Xy& b) {
        return std::abs(a.x - b.x) <= 2e-4 && std::abs(a.y - b.y) <= 2e-4;
    };
    const auto same_chromaticities = [&](const RgbSpace& other) {
        const RgbPrimaries& p = other.primaries();
        const RgbPrimaries& q = space.primaries();
        return near(p.red, q.red) && near(p.green, q.green) && near(p.blue, q.blue) &&
               near(other.white(), space.white());
    };
    if (!image.icc_profile.empty()) {
        const IccProfile profile = IccProfile::parse(image.icc_profile, "icc_profile");
        if (!profile.rgb_space()) {
            throw Error("icc_profile is " + profile.summary() + ", which cannot be compared with color_space '" +
                        name + "'; give one of them");
        }
        const RgbSpace& other = *profile.rgb_space();
        if (!same_chromaticities(other) || other.transfer().max_difference(space.transfer()) > 2e-4) {
            throw Error("icc_profile is " + profile.summary() + ", and color_space says '" + name +
                        "': they contradict each other; give one of them");
        }
    }
    if (!image.chromaticities.empty()) {
        const RgbSpace other = rgb_space_from_chromaticities(image.chromaticities, "chromaticities", "chromaticities");
        if (!same_chromaticities(other)) {
            throw Error("chromaticities describe other primaries or another white than color_space '" + name +
                        "': they contradict each other; give one of them");
        }
    }
}

ImageSpace image_space(const io::Image& image, const std::string& what) {
    ImageSpace s;
    // L*a*b* samples reach irid as libtiff's RGB rendering of them, which no profile describes.
    if (image.stored_model.ends_with("Lab")) {
        throw Error(what + ": holds " + image.stored_model + " samples (L*, a*, b*), which OpenImageIO converts "
                           "to RGB through libtiff's own display model, no colour space: convert the file "
                           "to RGB with a profile, or name a space to take that RGB as");
    }
    // PNG's cICP comes before every other colour chunk (PNG Third Edition §11.3.2.6).
    if (!image.png_cicp.empty()) return detail::png_cicp_space(image, what);
    if (image.icc_profile_rejected) {
        throw Error(what + ": ICC profile: damaged: " +
                    (image.icc_profile_damage.empty() ? std::string("the file's decoder rejected it")
                                                      : image.icc_profile_damage));
    }
    if (!image.icc_profile.empty()) {
        auto profile = std::make_shared<const IccProfile>(IccProfile::parse(image.icc_profile, what));
        s.encoded = true;
        s.origin = profile->summary();
        if (profile->rgb_space()) {
            s.builtin = matching_builtin_space(*profile->rgb_space());
            s.rgb = s.builtin != nullptr ? *s.builtin : *profile->rgb_space();
        } else {
            s.profile = std::move(profile);
        }
        return s;
    }
    if (image.stored_cmyk || !image.stored_model.empty()) {
        const std::string model = image.stored_model.empty() ? std::string("CMYK") : image.stored_model;
        throw Error(what + ": holds " + model + " samples without an ICC profile; OpenImageIO converted them to "
                           "RGB without one (R = (1 - C)(1 - K), ...), which is no colour space: convert "
                           "the file to RGB with its press profile, or name a space to take that RGB as");
    }
    if (image.chromaticities.size() == exr_xyz_chromaticities.size() &&
        std::equal(image.chromaticities.begin(), image.chromaticities.end(), exr_xyz_chromaticities.begin(),
                   [](float a, float b) { return std::abs(a - b) <= 1e-6f; })) {
        s.xyz = true;
        s.origin = "its EXR chromaticities of CIE XYZ (red 1, 0, green 0, 1, blue 0, 0, white 1/3, 1/3)";
        return s;
    }
    if (!image.chromaticities.empty()) {
        const RgbSpace exr = rgb_space_from_chromaticities(image.chromaticities, "exr-chromaticities", what);
        s.builtin = matching_builtin_space(exr, 2e-4, true);
        s.rgb = s.builtin != nullptr ? *s.builtin : exr;
        s.origin = fmt::format("its EXR chromaticities (red {:.4f}, {:.4f}, green {:.4f}, {:.4f}, blue {:.4f}, "
                               "{:.4f}, white {:.4f}, {:.4f})",
                               image.chromaticities[0], image.chromaticities[1], image.chromaticities[2],
                               image.chromaticities[3], image.chromaticities[4], image.chromaticities[5],
                               image.chromaticities[6], image.chromaticities[7]);
        return s;
    }
    if (image.png_srgb || image.png_gamma > 0.0 || !image.png_chromaticities.empty()) {
        return detail::png_chunks_space(image, what);
    }
    s.assumed = true;
    s.builtin = &srgb();
    s.rgb = srgb();
    s.encoded = image.stored_integer;
    s.origin = "no ICC profile or chromaticities";
    return s;
}

ColorSpace ImageSpace::colour_space() const noexcept {
    if (profile || xyz) return {SpaceFamily::xyz, nullptr};
    // The built-in space itself, not the copy: a conversion to it (or from it) is then the
    // identity, where a matrix through XYZ and back would leak 6e-17 of a huge channel into
    // the others.
    return {encoded ? SpaceFamily::rgb_encoded : SpaceFamily::rgb_linear, builtin != nullptr ? builtin : &*rgb};
}

void tag_image_xyz(io::Image& image) {
    image.color_space = "xyz";
    image.icc_profile.clear();
    image.adopted_neutral.clear();
    if (image.channels < 3) {
        image.chromaticities.clear();
        return;
    }
    image.chromaticities.assign(exr_xyz_chromaticities.begin(), exr_xyz_chromaticities.end());
}

void check_file_holds(const RgbSpace& space, io::ImageFormat format) {
    const TransferFunction::Kind kind = space.transfer().kind();
    if (format != io::ImageFormat::jpeg || (kind != TransferFunction::Kind::pq && kind != TransferFunction::Kind::hlg))
        return;
    throw Error(fmt::format("{} in a JPEG: its 8 bits show {}'s steps, and no JPEG tag says the curve, so readers "
                            "take the codes for sRGB; write PNG or TIFF (16 bits), or an EXR (linear)",
                            space.name(), kind == TransferFunction::Kind::pq ? "PQ" : "HLG"));
}

void tag_image(io::Image& image, const RgbSpace& space, io::ImageFormat format) {
    check_file_holds(space, format);
    if (image.channels < 3) {  // an RGB profile or chromaticities do not describe grey
        image.color_space = format == io::ImageFormat::exr ? space.name() + "-linear" : space.name();
        image.icc_profile.clear();
        image.chromaticities.clear();
        image.adopted_neutral.clear();
        return;
    }
    if (format == io::ImageFormat::exr) {
        image.color_space = space.name() + "-linear";
        const std::array<float, 8> c = exr_chromaticities(space);
        image.chromaticities.assign(c.begin(), c.end());
        image.icc_profile.clear();
        // OpenEXR's adoptedNeutral (ImfStandardAttributes.h): the white to show as neutral; said
        // when it is not the D65 that readers without chromaticities assume.
        const bool d65 = std::abs(space.white().x - d65_xy.x) < 1e-4 && std::abs(space.white().y - d65_xy.y) < 1e-4;
        if (d65) {
            image.adopted_neutral.clear();
        } else {
            image.adopted_neutral = {c[6], c[7]};
        }
    } else {
        image.color_space = space.name();
        // No ICC.1 curve holds PQ or ACEScct: such a file carries the space's name alone.
        if (!icc_curve_can_hold(space.transfer())) {
            image.icc_profile.clear();
        } else {
            image.icc_profile = make_icc_profile(space);
        }
        image.chromaticities.clear();
        image.adopted_neutral.clear();
    }
}

}  // namespace irid
