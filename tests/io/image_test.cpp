// irid_io: images through OpenImageIO (output files: output_file_test.cpp).
#include <irid/error.h>
#include <irid/io/output_file.h>
#include <irid/io/image.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace irid::io {
namespace {
namespace fs = std::filesystem;

/// A fresh, empty folder per test, removed afterwards.
class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("irid_io_test_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::permissions(m_dir, fs::perms::owner_all, fs::perm_options::add, ignored);
        fs::remove_all(m_dir, ignored);
    }
    /// The names of every file in the test's folder.
    [[nodiscard]] std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_dir)) {
            names.push_back(entry.path().filename().string());
        }
        return names;
    }
    fs::path m_dir;
};

/// A w × h image whose samples cover [0, 1] in many distinct values (including exactly 0 and 1)
/// and whose channel c of pixel i is unique, so a transposed or shuffled channel shows.
Image ramp(int w, int h, int channels) {
    Image image = Image::blank(w, h, channels);
    const std::size_t n = image.pixels.size();
    for (std::size_t i = 0; i < n; ++i) {
        image.pixels[i] =
            static_cast<float>(static_cast<double>((i * 7919) % n) / static_cast<double>(n - 1));
    }
    return image;
}

/// The format OpenImageIO itself reports for a file, to check the stored bit depth
/// independently of read_image.
OIIO::TypeDesc stored_format(const fs::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) return OIIO::TypeDesc::UNKNOWN;
    return in->spec().format;
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// --- round trips ----------------------------------------------------------------------------

TEST_F(ImageIo, ExrFloatRoundTripIsExact) {
    Image image = ramp(7, 5, 3);
    // Values no 8- or 16-bit format could hold: negative, above 1, tiny, huge.
    image.pixels[0] = -0.25f;
    image.pixels[1] = 1.0e-30f;
    image.pixels[2] = 65504.0f * 4.0f;
    image.pixels[3] = 0.1f;  // not representable in half
    image.color_space = "rec2020-linear";
    image.description = "irid test image";
    const fs::path path = m_dir / "round.exr";
    write_image(path, image);

    EXPECT_EQ(stored_format(path), OIIO::TypeDesc::FLOAT);
    const Image back = read_image(path);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.channels, 3);
    EXPECT_EQ(back.channel_names, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(back.pixels, image.pixels);  // bit for bit
    EXPECT_EQ(back.color_space, "rec2020-linear");
    EXPECT_EQ(back.description, "irid test image");
    EXPECT_FALSE(back.stored_integer);
    EXPECT_EQ(back.stored_bits, 32);
}

TEST_F(ImageIo, Png8BitRoundTripIsWithinHalfAStep) {
    const Image image = ramp(16, 9, 3);
    const fs::path path = m_dir / "round.png";
    write_image(path, image, {.bits = 8, .compression = {}});

    EXPECT_EQ(stored_format(path), OIIO::TypeDesc::UINT8);
    const Image back = read_image(path);
    ASSERT_EQ(back.pixels.size(), image.pixels.size());
    EXPECT_TRUE(back.stored_integer);
    EXPECT_EQ(back.stored_bits, 8);
    const double half_step = 0.5 / 255.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        ASSERT_LE(std::abs(static_cast<double>(back.pixels[i]) - image.pixels[i]), half_step + 1e-7)
            << i;
    }
    // The ends are exact.
    EXPECT_EQ(back.pixels[0], image.pixels[0]);
}

TEST_F(ImageIo, Tiff16BitRoundTripIsWithinHalfAStep) {
    const Image image = ramp(16, 9, 3);
    for (const char* name : {"round.tif", "round.TIFF"}) {
        const fs::path path = m_dir / name;
        write_image(path, image, {.bits = 16, .compression = {}});
        EXPECT_EQ(stored_format(path), OIIO::TypeDesc::UINT16) << name;
        const Image back = read_image(path);
        ASSERT_EQ(back.pixels.size(), image.pixels.size());
        EXPECT_EQ(back.stored_bits, 16);
        const double half_step = 0.5 / 65535.0;
        double worst = 0.0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            worst =
                std::max(worst, std::abs(static_cast<double>(back.pixels[i]) - image.pixels[i]));
        }
        EXPECT_LE(worst, half_step + 1e-9) << name;
        // Better than 8 bits could do: the 16 bits are really there.
        EXPECT_LT(worst, 0.5 / 255.0 / 100.0) << name;
    }
}

TEST_F(ImageIo, QuantisationRoundsToTheNearestCodeAndClamps) {
    Image image = Image::blank(6, 1, 1);
    // 0.5/255 rounds up to 1 (not truncated to 0); 0.49/255 rounds to 0; out-of-range values
    // clamp; NaN becomes 0.
    image.pixels = {0.5f / 255.0f + 1e-6f, 0.49f / 255.0f, 254.6f / 255.0f, -0.3f, 1.7f,
                    std::nanf("")};
    const fs::path path = m_dir / "codes.png";
    write_image(path, image);
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in);
    std::vector<unsigned char> codes(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, codes.data()));
    EXPECT_EQ(codes, (std::vector<unsigned char>{1, 0, 255, 0, 255, 0}));
}

TEST_F(ImageIo, AlphaAndExtraChannelsArePreserved) {
    // RGBA in PNG and TIFF: alpha stored as is, colour not divided or multiplied by it.
    Image rgba = ramp(8, 8, 4);
    for (std::size_t p = 0; p < rgba.pixel_count(); ++p)
        rgba.pixels[p * 4 + 3] = static_cast<float>(p % 3) * 0.5f;
    for (const char* name : {"alpha.png", "alpha.tif"}) {
        const fs::path path = m_dir / name;
        write_image(path, rgba, {.bits = 16, .compression = {}});
        const Image back = read_image(path);
        ASSERT_EQ(back.channels, 4) << name;
        EXPECT_EQ(back.channel_index("A"), 3) << name;
        for (std::size_t i = 0; i < rgba.pixels.size(); ++i) {
            ASSERT_NEAR(back.pixels[i], rgba.pixels[i], 0.5 / 65535.0 + 1e-9) << name << " " << i;
        }
    }
    // EXR with alpha, depth and an arbitrary extra channel, all float and exact.
    Image extra = ramp(5, 4, 6);
    extra.channel_names = {"R", "G", "B", "A", "Z", "mask"};
    const fs::path path = m_dir / "extra.exr";
    write_image(path, extra);
    const Image back = read_image(path);
    ASSERT_EQ(back.channels, 6);
    for (int c = 0; c < 6; ++c) {
        const int b = back.channel_index(extra.channel_names[static_cast<std::size_t>(c)]);
        ASSERT_GE(b, 0) << extra.channel_names[static_cast<std::size_t>(c)];
        for (int y = 0; y < 4; ++y) {
            for (int x = 0; x < 5; ++x) ASSERT_EQ(back.at(x, y, b), extra.at(x, y, c));
        }
    }
}

TEST_F(ImageIo, ColourSpaceMetadataIsWritten) {
    Image image = ramp(2, 2, 3);
    image.color_space = "display-p3-linear";
    image.description = "clipped by irid";
    for (const char* name : {"meta.exr", "meta.tif"}) {
        write_image(m_dir / name, image, {.bits = 16, .compression = {}});
        auto in = OIIO::ImageInput::open((m_dir / name).string());
        ASSERT_TRUE(in) << name;
        EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "clipped by irid") << name;
    }
    EXPECT_EQ(read_image(m_dir / "meta.exr").color_space, "display-p3-linear");
    image.color_space = "srgb";
    write_image(m_dir / "meta.png", image);
    EXPECT_EQ(read_image(m_dir / "meta.png").color_space, "srgb");
    // Files from elsewhere: OpenImageIO's own name (it calls every EXR "Linear").
    auto out = OIIO::ImageOutput::create("openexr");
    ASSERT_TRUE(out);
    ASSERT_TRUE(
        out->open((m_dir / "plain.exr").string(), OIIO::ImageSpec(1, 1, 3, OIIO::TypeFloat)));
    const float black[3] = {0.0f, 0.0f, 0.0f};
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, black));
    ASSERT_TRUE(out->close());
    EXPECT_EQ(read_image(m_dir / "plain.exr").color_space, "Linear");
}

// --- errors ---------------------------------------------------------------------------------

TEST_F(ImageIo, UnsupportedExtensionIsAnErrorNamingTheFile) {
    const Image image = ramp(2, 2, 3);
    for (const char* name : {"out.bmp", "out.hdr", "out", "out.exr.bak"}) {
        try {
            write_image(m_dir / name, image);
            ADD_FAILURE() << name << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(".exr"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(files().empty());
    EXPECT_THROW(write_image(m_dir / "bits.png", image, {.bits = 12, .compression = {}}), Error);
    // JPEG: 8 bits, no alpha, a quality of 1 to 100.
    EXPECT_THROW(write_image(m_dir / "deep.jpg", image, {.bits = 16, .compression = {}}), Error);
    EXPECT_THROW(write_image(m_dir / "alpha.jpg", ramp(2, 2, 4)), Error);
    EXPECT_THROW(write_image(m_dir / "q.jpg", image, {.bits = 8, .compression = "jpeg:0"}), Error);
    EXPECT_THROW(write_image(m_dir / "q.jpg", image, {.bits = 8, .compression = "zip"}), Error);
    EXPECT_TRUE(files().empty());
}

TEST_F(ImageIo, MissingOrUnwritableFolderIsAnErrorAndLeavesNothing) {
    const Image image = ramp(2, 2, 3);
    // A folder that does not exist.
    EXPECT_THROW(write_image(m_dir / "no-such-folder" / "out.exr", image), Error);
    // A "folder" that is a file.
    std::ofstream(m_dir / "plain").put('x');
    EXPECT_THROW(write_image(m_dir / "plain" / "out.png", image), Error);
    // A folder nobody may create files in, not even root.
    try {
        write_image("/proc/irid-io-test.exr", image);
        ADD_FAILURE() << "/proc accepted a file";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/proc/irid-io-test.exr"), std::string::npos)
            << e.what();
    }
    // A folder without write permission (permissions do not stop root).
    if (::geteuid() != 0) {
        const fs::path locked = m_dir / "locked";
        fs::create_directory(locked);
        fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
        EXPECT_THROW(write_image(locked / "out.tif", image), Error);
        EXPECT_THROW(write_output_file(locked / "out.csv", "1,2,3\n"), Error);
        fs::permissions(locked, fs::perms::owner_all);
        EXPECT_TRUE(fs::is_empty(locked));
    }
    EXPECT_EQ(files(), std::vector<std::string>{"plain"});
    // The destination is a folder.
    fs::create_directory(m_dir / "folder.exr");
    EXPECT_THROW(write_image(m_dir / "folder.exr", image), Error);
}

TEST_F(ImageIo, InconsistentImageIsAnErrorAndLeavesNothing) {
    Image image = ramp(4, 4, 3);
    image.pixels.pop_back();
    EXPECT_THROW(write_image(m_dir / "short.exr", image), Error);
    image = ramp(4, 4, 3);
    image.channel_names = {"R", "G"};
    EXPECT_THROW(write_image(m_dir / "names.exr", image), Error);
    EXPECT_THROW((void)Image::blank(0, 4, 3), Error);
    // PNG holds at most four channels: OpenImageIO refuses, the temporary file goes away.
    EXPECT_THROW(write_image(m_dir / "six.png", ramp(2, 2, 6)), Error);
    EXPECT_TRUE(files().empty());
}

TEST_F(ImageIo, ReadErrorsNameTheFile) {
    const auto expect_error_naming = [](const fs::path& path) {
        try {
            (void)read_image(path);
            ADD_FAILURE() << path << " was read";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        }
    };
    expect_error_naming(m_dir / "missing.exr");
    std::ofstream(m_dir / "text.png") << "this is not a PNG file\n";
    expect_error_naming(m_dir / "text.png");
    // A truncated EXR.
    write_image(m_dir / "whole.exr", ramp(64, 64, 3));
    const std::string bytes = slurp(m_dir / "whole.exr");
    std::ofstream(m_dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    expect_error_naming(m_dir / "cut.exr");
    expect_error_naming(m_dir);
}

// --- atomic writes --------------------------------------------------------------------------

TEST_F(ImageIo, NoTemporaryFileIsLeftOnSuccessOrFailure) {
    write_image(m_dir / "a.exr", ramp(3, 3, 3));
    write_image(m_dir / "b.png", ramp(3, 3, 4));
    write_image(m_dir / "c.tiff", ramp(3, 3, 1), {.bits = 16, .compression = {}});
    write_output_file(m_dir / "d.csv", "R,G,B\n1,0,0\n");
    EXPECT_THROW(write_image(m_dir / "e.png", ramp(3, 3, 5)), Error);  // fails inside OIIO
    std::vector<std::string> names = files();
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"a.exr", "b.png", "c.tiff", "d.csv"}));
    EXPECT_EQ(slurp(m_dir / "d.csv"), "R,G,B\n1,0,0\n");
}

TEST_F(ImageIo, AFailedWriteKeepsTheExistingFile) {
    write_output_file(m_dir / "keep.png", "old");
    EXPECT_THROW(write_image(m_dir / "keep.png", ramp(2, 2, 7)), Error);
    EXPECT_EQ(slurp(m_dir / "keep.png"), "old");
    // A successful write replaces it whole.
    write_image(m_dir / "keep.png", ramp(2, 2, 3));
    EXPECT_EQ(read_image(m_dir / "keep.png").width, 2);
    EXPECT_EQ(files(), std::vector<std::string>{"keep.png"});
}

TEST_F(ImageIo, TextFileErrorsNameThePath) {
    try {
        write_output_file(m_dir / "missing" / "out.csv", "x");
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("out.csv"), std::string::npos) << e.what();
    }
    EXPECT_THROW(write_output_file(m_dir, "x"), Error);
    EXPECT_THROW(write_output_file("/proc/irid-io-test.csv", "x"), Error);
    write_output_file(m_dir / "empty.csv", "");
    EXPECT_EQ(slurp(m_dir / "empty.csv"), "");
    EXPECT_EQ(files(), std::vector<std::string>{"empty.csv"});
}

}  // namespace
}  // namespace irid::io
