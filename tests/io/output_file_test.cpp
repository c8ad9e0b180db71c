// irid_io: output files — whole or not at all, and never replacing what is not a regular file
// (include/irid/io/output_file.h), and the limits on what read_image accepts.
#include <irid/error.h>
#include <irid/io/image.h>
#include <irid/io/output_file.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

namespace irid::io {
namespace {
namespace fs = std::filesystem;

class OutputFiles : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("irid_output_test_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(m_dir, ignored);
    }
    /// The names in the test's folder, sorted.
    [[nodiscard]] std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_dir))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    fs::path m_dir;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// What a writer sends through a FIFO, read until it closes, or what arrived within 10 s (a
/// writer that never opens the FIFO must fail the test, not hang it).
std::string read_fifo(const fs::path& p) {
    const int fd = ::open(p.c_str(), O_RDONLY | O_NONBLOCK);
    if (fd < 0) return {};
    std::string out;
    bool opened = false;  // a writer has connected (data seen)
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
        pollfd pfd{fd, POLLIN, 0};
        if (::poll(&pfd, 1, 100) <= 0) continue;
        char buffer[4096];
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            out.append(buffer, static_cast<std::size_t>(n));
            opened = true;
        } else if (n == 0 && opened) {
            break;  // the writer closed it
        } else if (n == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));  // no writer yet
        }
    }
    ::close(fd);
    return out;
}

void spit(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

mode_t mode_of(const fs::path& p) {
    struct stat st {};
    EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
    return st.st_mode;
}

/// The message of the irid::Error that `f` throws ("" and a failure when it throws none).
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no irid::Error was thrown";
    return {};
}

Image ramp(int w, int h, int channels) {
    Image image = Image::blank(w, h, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>((i * 37) % 101) / 100.0f;
    return image;
}

/// Files may grow to at most `bytes` while it lives: writes beyond fail with EFBIG, as on a full
/// disk (SIGXFSZ ignored, so the process is told by the error instead of being killed).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &m_saved);
        m_handler = std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{bytes, m_saved.rlim_max};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_handler);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit m_saved{};
    void (*m_handler)(int) = nullptr;
};

// --- regular files --------------------------------------------------------------------------

TEST_F(OutputFiles, NothingIsVisibleBeforeCommitAndNothingIsLeftUnlessCommitted) {
    {
        OutputFile file(m_dir / "x.txt");
        file.write("partial");
        EXPECT_FALSE(fs::exists(m_dir / "x.txt"));
        ASSERT_EQ(files().size(), 1u);  // the temporary file, beside the target
    }
    EXPECT_TRUE(files().empty());
    {
        OutputFile file(m_dir / "y.txt");
        file.write("whole");
        file.commit();
        EXPECT_THROW(file.commit(), Error);
    }
    EXPECT_EQ(slurp(m_dir / "y.txt"), "whole");
    EXPECT_EQ(files(), std::vector<std::string>{"y.txt"});
    // Two outputs to one target never share a temporary file; the last commit wins.
    OutputFile a(m_dir / "t.txt");
    OutputFile b(m_dir / "t.txt");
    a.write("a");
    b.write("b");
    a.commit();
    b.commit();
    EXPECT_EQ(slurp(m_dir / "t.txt"), "b");
}

TEST_F(OutputFiles, SeveralFilesAreRenamedOnlyOnceAllAreWritten) {
    // A folder where the second file should go: refused before anything is renamed, so the
    // first file's old bytes stay and no temporary file is left.
    { std::ofstream(m_dir / "a.txt") << "old"; }
    fs::create_directories(m_dir / "b.txt");
    EXPECT_THROW((void)write_output_files(m_dir, {{"a.txt", "new"}, {"b.txt", "x"}}), Error);
    EXPECT_EQ(slurp(m_dir / "a.txt"), "old");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.txt", "b.txt"}));
    // All written, into a folder made for them; the paths come back in order.
    const std::vector<fs::path> paths =
        write_output_files(m_dir / "new" / "sub", {{"a.txt", "1"}, {"c.txt", "22"}});
    ASSERT_EQ(paths.size(), 2u);
    EXPECT_EQ(paths[0], m_dir / "new" / "sub" / "a.txt");
    EXPECT_EQ(slurp(paths[0]), "1");
    EXPECT_EQ(slurp(paths[1]), "22");
}

TEST_F(OutputFiles, ASetIsReplacedWholeOrNotAtAll) {
    // The old set of three; the third rename fails (injected), after the first two are in place:
    // the old set comes back whole, with nothing left beside it. A set whose second file is new
    // loses that file again.
    spit(m_dir / "a.txt", "old a");
    spit(m_dir / "c.txt", "old c");
    spit(m_dir / "d.txt", "old d");
    const auto fail_at = [](std::size_t k) {
        return [k](std::size_t i) {
            if (i == k) throw Error("injected rename failure");
        };
    };
    EXPECT_THROW((void)write_output_files(m_dir, {{"a.txt", "new a"}, {"c.txt", "new c"}, {"d.txt", "new d"}},
                                          fail_at(2)),
                 Error);
    EXPECT_EQ(slurp(m_dir / "a.txt"), "old a");
    EXPECT_EQ(slurp(m_dir / "c.txt"), "old c");
    EXPECT_EQ(slurp(m_dir / "d.txt"), "old d");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.txt", "c.txt", "d.txt"}));
    EXPECT_THROW((void)write_output_files(m_dir, {{"a.txt", "new a"}, {"b.txt", "new b"}, {"d.txt", "new d"}},
                                          fail_at(2)),
                 Error);
    EXPECT_EQ(slurp(m_dir / "a.txt"), "old a");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.txt", "c.txt", "d.txt"}));
    // Without a failure the new set is in place, and nothing kept aside is left.
    (void)write_output_files(m_dir, {{"a.txt", "new a"}, {"b.txt", "new b"}, {"d.txt", "new d"}});
    EXPECT_EQ(slurp(m_dir / "a.txt"), "new a");
    EXPECT_EQ(slurp(m_dir / "b.txt"), "new b");
    EXPECT_EQ(slurp(m_dir / "d.txt"), "new d");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.txt", "b.txt", "c.txt", "d.txt"}));
}

TEST_F(OutputFiles, AnExistingFileKeepsItsPermissions) {
    spit(m_dir / "secret.csv", "old");
    ::chmod((m_dir / "secret.csv").c_str(), 0600);
    write_output_file(m_dir / "secret.csv", "new");
    EXPECT_EQ(slurp(m_dir / "secret.csv"), "new");
    EXPECT_EQ(mode_of(m_dir / "secret.csv") & 07777, 0600u);
    ::chmod((m_dir / "secret.csv").c_str(), 0751);
    write_image(m_dir / "secret.png", ramp(2, 2, 3));
    ::chmod((m_dir / "secret.png").c_str(), 0640);
    write_image(m_dir / "secret.png", ramp(3, 3, 3));
    EXPECT_EQ(mode_of(m_dir / "secret.png") & 07777, 0640u);
    EXPECT_EQ(read_image(m_dir / "secret.png").width, 3);
}

TEST_F(OutputFiles, ANewFileGetsTheUmasksMode) {
    const mode_t saved = ::umask(027);
    write_output_file(m_dir / "new.csv", "x");
    ::umask(saved);
    EXPECT_EQ(mode_of(m_dir / "new.csv") & 07777, 0640u);
}

TEST_F(OutputFiles, AnExistingFilesOwnerIsKeptWhereThatIsAllowed) {
    if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file to another user";
    spit(m_dir / "theirs.csv", "old");
    ASSERT_EQ(::chown((m_dir / "theirs.csv").c_str(), 65534, 65534), 0);
    write_output_file(m_dir / "theirs.csv", "new");
    struct stat st {};
    ASSERT_EQ(::stat((m_dir / "theirs.csv").c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 65534u);
    EXPECT_EQ(st.st_gid, 65534u);
}

TEST_F(OutputFiles, ALongNameStillFitsBesideItsTemporaryFile) {
    const std::string name = std::string(250, 'n') + ".csv";  // 254 of NAME_MAX's 255 bytes
    write_output_file(m_dir / name, "long");
    EXPECT_EQ(slurp(m_dir / name), "long");
    EXPECT_EQ(files(), std::vector<std::string>{name});
}

// --- links, devices, FIFOs, descriptors ----------------------------------------------------

TEST_F(OutputFiles, ASymbolicLinkIsFollowedAndItsTargetReplaced) {
    fs::create_directory(m_dir / "real");
    spit(m_dir / "real" / "data.csv", "old");
    ::chmod((m_dir / "real" / "data.csv").c_str(), 0600);
    fs::create_symlink("real/data.csv", m_dir / "link.csv");
    fs::create_symlink("link.csv", m_dir / "link2.csv");  // a chain
    write_output_file(m_dir / "link2.csv", "new");
    EXPECT_TRUE(S_ISLNK(mode_of(m_dir / "link.csv")));
    EXPECT_TRUE(S_ISLNK(mode_of(m_dir / "link2.csv")));
    EXPECT_EQ(slurp(m_dir / "real" / "data.csv"), "new");
    EXPECT_EQ(mode_of(m_dir / "real" / "data.csv") & 07777, 0600u);
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir / "real"), fs::directory_iterator()), 1);
    // A dangling link creates its target, as a shell's > does.
    fs::create_symlink("real/made.csv", m_dir / "dangling.csv");
    write_output_file(m_dir / "dangling.csv", "made");
    EXPECT_EQ(slurp(m_dir / "real" / "made.csv"), "made");
    // A loop is refused, naming the path.
    fs::create_symlink("loop-b", m_dir / "loop-a");
    fs::create_symlink("loop-a", m_dir / "loop-b");
    EXPECT_NE(error_of([&] { write_output_file(m_dir / "loop-a", "x"); }).find("loop-a"),
              std::string::npos);
}

TEST_F(OutputFiles, AFifoIsWrittenIntoAndStaysAFifo) {
    const fs::path fifo = m_dir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = read_fifo(fifo); });
    write_output_file(fifo, "through the pipe\n");
    reader.join();
    EXPECT_EQ(received, "through the pipe\n");
    EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
    // An image too: assembled in memory (a FIFO cannot seek) and written whole. The format
    // comes from the name's extension, here a link's.
    fs::create_symlink("pipe", m_dir / "pipe.png");
    std::string png;
    std::thread image_reader([&] { png = read_fifo(fifo); });
    write_image(m_dir / "pipe.png", ramp(5, 4, 3));
    image_reader.join();
    spit(m_dir / "copy.png", png);
    EXPECT_EQ(read_image(m_dir / "copy.png").width, 5);
    EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
    EXPECT_EQ(files(), (std::vector<std::string>{"copy.png", "pipe", "pipe.png"}));
}

TEST_F(OutputFiles, ACharacterDeviceIsWrittenIntoAndItsErrorsReported) {
    if (::geteuid() != 0) GTEST_SKIP() << "mknod of a character device needs root";
    // Copies of /dev/null (1, 3) and /dev/full (1, 7) inside the test's folder.
    const fs::path null_device = m_dir / "null", full_device = m_dir / "full";
    ASSERT_EQ(::mknod(null_device.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
    ASSERT_EQ(::mknod(full_device.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);
    write_output_file(null_device, "discarded");
    EXPECT_TRUE(S_ISCHR(mode_of(null_device)));
    const std::string message = error_of([&] { write_output_file(full_device, "no room"); });
    EXPECT_NE(message.find(full_device.string()), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(ENOSPC)), std::string::npos) << message;
    EXPECT_TRUE(S_ISCHR(mode_of(full_device)));
    fs::create_symlink("full", m_dir / "full.png");
    EXPECT_NE(error_of([&] { write_image(m_dir / "full.png", ramp(4, 4, 3)); })
                  .find(std::strerror(ENOSPC)),
              std::string::npos);
    EXPECT_TRUE(S_ISCHR(mode_of(full_device)));
    EXPECT_EQ(files(), (std::vector<std::string>{"full", "full.png", "null"}));
}

TEST_F(OutputFiles, ABlockDeviceASocketAndAFolderAreRefusedBeforeAnythingIsWritten) {
    if (::geteuid() == 0) {
        const fs::path block = m_dir / "block";
        ASSERT_EQ(::mknod(block.c_str(), S_IFBLK | 0600, makedev(7, 200)), 0);
        EXPECT_NE(error_of([&] { (void)check_output_path(block); }).find("block device"),
                  std::string::npos);
        EXPECT_THROW(write_output_file(block, "x"), Error);
        EXPECT_TRUE(S_ISBLK(mode_of(block)));
    }
    const fs::path socket_path = m_dir / "sock";
    const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strncpy(address.sun_path, socket_path.c_str(), sizeof address.sun_path - 1);
    ASSERT_EQ(::bind(s, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    EXPECT_NE(error_of([&] { write_output_file(socket_path, "x"); }).find("socket"),
              std::string::npos);
    EXPECT_TRUE(S_ISSOCK(mode_of(socket_path)));
    ::close(s);
    EXPECT_NE(error_of([&] { write_output_file(m_dir, "x"); }).find("directory"),
              std::string::npos);
    EXPECT_NE(error_of([&] { write_output_file(m_dir / "no" / "x.csv", "x"); }).find("does not exist"),
              std::string::npos);
    EXPECT_THROW(write_output_file("", "x"), Error);
}

TEST_F(OutputFiles, AnOpenDescriptorIsWrittenToAsItIs) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const std::string path = "/dev/fd/" + std::to_string(fds[1]);
    EXPECT_EQ(check_output_path(path).descriptor, fds[1]);
    write_output_file(path, "to the pipe");
    ::close(fds[1]);
    std::array<char, 64> buffer{};
    const ssize_t n = ::read(fds[0], buffer.data(), buffer.size());
    ::close(fds[0]);
    EXPECT_EQ(std::string(buffer.data(), static_cast<std::size_t>(std::max<ssize_t>(n, 0))),
              "to the pipe");
    // An append-mode descriptor keeps appending (it is not reopened and truncated).
    spit(m_dir / "log", "first\n");
    const int log = ::open((m_dir / "log").c_str(), O_WRONLY | O_APPEND);
    write_output_file("/proc/self/fd/" + std::to_string(log), "second\n");
    ::close(log);
    EXPECT_EQ(slurp(m_dir / "log"), "first\nsecond\n");
    // A descriptor open for reading only is refused.
    const int reading = ::open((m_dir / "log").c_str(), O_RDONLY);
    EXPECT_NE(error_of([&] { write_output_file("/dev/fd/" + std::to_string(reading), "x"); })
                  .find("reading only"),
              std::string::npos);
    ::close(reading);
}

// --- failures leave the destination as it was ----------------------------------------------

TEST_F(OutputFiles, AFullDiskFailsEveryFormatAndKeepsTheOldFile) {
    // Old contents that must survive, one per format.
    const std::vector<std::string> names{"out.csv", "out.png", "out.tif", "out.exr"};
    for (const std::string& name : names) spit(m_dir / name, "old " + name);
    // Noise, which no format compresses much: far beyond 4 KiB in each.
    Image big = Image::blank(256, 256, 3);
    std::uint32_t state = 12345;
    for (float& v : big.pixels) {
        state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
        v = static_cast<float>(state >> 8) / 16777216.0f;
    }
    std::vector<std::string> messages;
    {
        const FileSizeLimit limit(4096);
        messages.push_back(error_of([&] { write_output_file(m_dir / "out.csv", std::string(10000, 'x')); }));
        for (std::size_t i = 1; i < names.size(); ++i)
            messages.push_back(error_of([&] { write_image(m_dir / names[i], big); }));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_NE(messages[i].find(names[i]), std::string::npos) << messages[i];
        EXPECT_NE(messages[i].find(std::strerror(EFBIG)), std::string::npos) << messages[i];
        EXPECT_TRUE(slurp(m_dir / names[i]) == "old " + names[i]) << names[i] << " was changed";
    }
    std::vector<std::string> sorted = names;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(files(), sorted);  // no temporary file left behind
}

TEST_F(OutputFiles, ImagesWrittenThroughTheOutputReadBack) {
    for (const char* name : {"a.png", "a.tif", "a.exr"}) {
        // With a colour space: OpenImageIO 2.4 turned "srgb" into a TIFF Exif directory that its
        // writer linked as the file's first directory, unreadable (the image fuzzer's image-1).
        Image image = ramp(7, 5, 4);
        image.color_space = "srgb";
        write_image(m_dir / name, image);
        const Image back = read_image(m_dir / name);
        EXPECT_EQ(back.width, 7) << name;
        EXPECT_EQ(back.height, 5) << name;
        EXPECT_EQ(back.channels, 4) << name;
    }
    write_image(m_dir / "b.tif", ramp(9, 3, 3), {.bits = 16, .compression = {}});
    EXPECT_EQ(read_image(m_dir / "b.tif").stored_bits, 16);
}

// --- what read_image accepts ------------------------------------------------------------------

/// CRC-32 of PNG chunks (ISO/IEC 15948 Annex D: polynomial 0xEDB88320, reflected).
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (const char ch : bytes) {
        c ^= static_cast<unsigned char>(ch);
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

std::string big_endian(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
            static_cast<char>(v)};
}

/// A PNG that declares width × height RGB pixels but holds almost no data.
std::string png_declaring(std::uint32_t width, std::uint32_t height) {
    std::string ihdr = "IHDR" + big_endian(width) + big_endian(height);
    ihdr += std::string{8, 2, 0, 0, 0};  // 8 bits, RGB, deflate, no filter, no interlace
    std::string idat = "IDAT" + std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
    return std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(crc32(ihdr)) +
           big_endian(8) + idat + big_endian(crc32(idat)) + big_endian(0) + "IEND" +
           big_endian(crc32("IEND"));
}

TEST_F(OutputFiles, AnImageDeclaringMoreThanTheLimitIsRefusedBeforeAllocating) {
    spit(m_dir / "huge.png", png_declaring(16000, 16000));
    const std::string message = error_of([&] { (void)read_image(m_dir / "huge.png"); });
    EXPECT_NE(message.find("huge.png"), std::string::npos) << message;
    EXPECT_NE(message.find("16000 x 16000"), std::string::npos) << message;
    EXPECT_NE(message.find("67108864"), std::string::npos) << message;
    spit(m_dir / "vast.png", png_declaring(100000, 100000));
    EXPECT_NE(error_of([&] { (void)read_image(m_dir / "vast.png"); }).find("100000 x 100000"),
              std::string::npos);
    // Within a caller's tighter limits, or beyond them.
    write_image(m_dir / "small.png", ramp(20, 10, 3));
    EXPECT_EQ(read_image(m_dir / "small.png", {.max_pixels = 200}).width, 20);
    EXPECT_THROW((void)read_image(m_dir / "small.png", {.max_pixels = 199}), Error);
    EXPECT_THROW((void)read_image(m_dir / "small.png", {.max_pixels = 1000, .max_samples = 599}),
                 Error);
    EXPECT_THROW((void)read_image(m_dir / "small.png", {.max_channels = 2}), Error);
}

TEST_F(OutputFiles, HeadersThatDeclareMoreThanTheFileHoldsAreRefusedBeforeDecoding) {
    // The image fuzzer's findings (tests/fuzz/regressions/image): a few hundred bytes whose
    // header makes a decoder (or irid) allocate gigabytes before it reads them.
    const fs::path found = fs::path(IRID_FUZZ_REGRESSIONS_DIR) / "image";
    const struct {
        const char* file;
        const char* message;
    } cases[] = {
        {"png-8192x8192-rgba-109-bytes.png",
         "8192 x 8192 pixels need 268443648 bytes of image data, and its 52 bytes of compressed "
         "data cannot hold them"},
        {"png-chunk-length-1.8gb-363-bytes.png", "its tEXt chunk at byte 54 declares 1795162230 bytes"},
        {"exr-attribute-size-2gb-521-bytes.exr", "declares 1852780307 bytes, and 311 remain"},
        {"png-truncated-oiio-leak.png", "its tEXt chunk at byte 155 declares 102 bytes, and 14 remain"},
    };
    for (const auto& c : cases) {
        const std::string message = error_of([&] { (void)read_image(found / c.file); });
        EXPECT_NE(message.find(c.file), std::string::npos) << message;
        EXPECT_NE(message.find(": truncated or corrupt: "), std::string::npos) << message;
        EXPECT_NE(message.find(c.message), std::string::npos) << message;
    }
    // A real image compressed as far as deflate goes (one colour, about 1020-fold) still reads,
    // and an EXR whose data window alone is beyond the limit is refused from its header.
    Image flat = Image::blank(2048, 1024, 3);
    write_image(m_dir / "flat.png", flat);
    EXPECT_EQ(read_image(m_dir / "flat.png").width, 2048);
    write_image(m_dir / "window.exr", ramp(16, 16, 3));
    EXPECT_NE(error_of([&] { (void)read_image(m_dir / "window.exr", {.max_pixels = 255}); })
                  .find("the image declares 16 x 16 pixels"),
              std::string::npos);
}

TEST_F(OutputFiles, AFifoIsNotReadAsAnImage) {
    const fs::path fifo = m_dir / "in.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Refused at once: nobody writes to it, so opening it would block forever.
    EXPECT_NE(error_of([&] { (void)read_image(fifo); }).find("FIFO"), std::string::npos);
}

}  // namespace
}  // namespace irid::io
