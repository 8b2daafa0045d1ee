// PNG round trips and the shared image-comparison helpers that golden-image tests rely on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/png_io.hpp"
#include "support/test_paths.hpp"

namespace {

using stipple::Image;

// A deterministic gradient with every channel distinct, so a swapped channel or a flipped row
// shows up in the round trip.
Image make_pattern(int width, int height, int channels) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels.resize(static_cast<size_t>(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.pixels[(static_cast<size_t>(y) * width + x) * channels + c] =
                    static_cast<uint8_t>((x * 7 + y * 13 + c * 61) & 0xff);
    return image;
}

// Checks that `fn` throws stipple::Error whose single-line message contains `needle`.
template <class Fn>
void expect_error(Fn&& fn, const std::string& needle) {
    try {
        fn();
        FAIL() << "expected stipple::Error containing '" << needle << "'";
    } catch (const stipple::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(needle), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "error must be one line: " << what;
    }
}

}  // namespace

TEST(PngIo, RoundTripKeepsEveryByteForEachChannelCount) {
    const auto dir = stipple::test::temp_dir("png_round_trip");
    for (int channels = 1; channels <= 4; ++channels) {
        const Image original = make_pattern(37, 23, channels);  // odd sizes: no row padding luck
        const std::string path = (dir / ("img" + std::to_string(channels) + ".png")).string();
        stipple::write_png(path, original);
        const Image back = stipple::read_png(path);
        EXPECT_EQ(back.width, original.width);
        EXPECT_EQ(back.height, original.height);
        EXPECT_EQ(back.channels, original.channels);
        EXPECT_EQ(back.pixels, original.pixels) << channels << " channels";
        EXPECT_EQ(stipple::fraction_differing(original, back, 0), 0.0);
    }
}

TEST(PngIo, WriteCreatesParentFolders) {
    const auto dir = stipple::test::temp_dir("png_parents");
    const std::string path = (dir / "a" / "b" / "c.png").string();
    stipple::write_png(path, make_pattern(4, 3, 3));
    EXPECT_EQ(stipple::read_png(path).width, 4);
}

// An image is written beside and renamed into place (io/output_file.hpp), keeping the old file's mode; a link
// at the path is the user's to name and is written through, as before, not replaced by a file.
TEST(PngIo, WriteKeepsTheModeAndWritesThroughALink) {
    namespace fs = std::filesystem;
    const auto dir = stipple::test::temp_dir("png_mode_and_link");
    const std::string path = (dir / "private.png").string();
    stipple::write_png(path, make_pattern(4, 3, 3));
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
    stipple::write_png(path, make_pattern(5, 3, 3));
    EXPECT_EQ(stipple::read_png(path).width, 5);
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);

    const fs::path real = dir / "real.png", link = dir / "link.png";
    stipple::write_png(real.string(), make_pattern(4, 3, 3));
    fs::create_symlink(real.filename(), link);
    stipple::write_png(link.string(), make_pattern(6, 3, 3));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(stipple::read_png(real.string()).width, 6);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".part-"), std::string::npos) << entry.path();
}

TEST(PngIo, FractionDifferingCountsPixelsOverTolerance) {
    Image a = make_pattern(10, 10, 3);
    Image b = a;
    // 5 pixels differ by 3 in one channel, 10 more by 20 in one channel.
    for (int i = 0; i < 5; ++i) b.pixels[(static_cast<size_t>(i) * 3) + 1] += 3;
    for (int i = 10; i < 20; ++i) {
        uint8_t& v = b.pixels[static_cast<size_t>(i) * 3];
        v = static_cast<uint8_t>(v < 128 ? v + 20 : v - 20);
    }
    EXPECT_DOUBLE_EQ(stipple::fraction_differing(a, b, 0), 15.0 / 100.0);
    EXPECT_DOUBLE_EQ(stipple::fraction_differing(a, b, 2), 15.0 / 100.0);
    EXPECT_DOUBLE_EQ(stipple::fraction_differing(a, b, 3), 10.0 / 100.0);
    EXPECT_DOUBLE_EQ(stipple::fraction_differing(a, b, 255), 0.0);
    EXPECT_DOUBLE_EQ(stipple::fraction_differing(b, a, 3), 10.0 / 100.0);  // symmetric
}

TEST(PngIo, FractionDifferingRejectsMismatchedSizes) {
    expect_error([] { stipple::fraction_differing(make_pattern(4, 4, 3), make_pattern(4, 5, 3), 0); },
                 "sizes differ");
    expect_error([] { stipple::fraction_differing(make_pattern(4, 4, 3), make_pattern(4, 4, 4), 0); },
                 "sizes differ");
}

TEST(PngIo, LuminanceOfGreyAndColour) {
    Image grey;
    grey.width = 2;
    grey.height = 1;
    grey.channels = 1;
    grey.pixels = {17, 200};
    EXPECT_EQ(stipple::luminance(grey, 0, 0), 17);
    EXPECT_EQ(stipple::luminance(grey, 1, 0), 200);

    Image rgba;
    rgba.width = 1;
    rgba.height = 3;
    rgba.channels = 4;
    rgba.pixels = {255, 255, 255, 0,  // white, alpha ignored
                   0, 0, 0, 255,      // black
                   255, 0, 0, 255};   // pure red: Rec. 601 weight 0.299
    EXPECT_EQ(stipple::luminance(rgba, 0, 0), 255);
    EXPECT_EQ(stipple::luminance(rgba, 0, 1), 0);
    EXPECT_EQ(stipple::luminance(rgba, 0, 2), 76);
    expect_error([&] { stipple::luminance(rgba, 1, 0); }, "outside");
    expect_error([&] { stipple::luminance(rgba, 0, -1); }, "outside");
}

TEST(PngIo, ReadMissingFileFailsWithPath) {
    const auto dir = stipple::test::temp_dir("png_missing");
    const std::string path = (dir / "nope.png").string();
    expect_error([&] { stipple::read_png(path); }, path + ": ");
}

TEST(PngIo, ReadGarbageFileFailsWithPath) {
    const auto dir = stipple::test::temp_dir("png_garbage");
    const std::string path = (dir / "garbage.png").string();
    {
        std::ofstream out(path, std::ios::binary);
        out << "this is not a PNG at all\n\x01\x02\x03";
    }
    expect_error([&] { stipple::read_png(path); }, path + ": ");
    // A truncated real PNG must fail too, not return a half image.
    const std::string good = (dir / "good.png").string();
    stipple::write_png(good, make_pattern(64, 64, 3));
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string truncated = (dir / "truncated.png").string();
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    expect_error([&] { stipple::read_png(truncated); }, truncated + ": ");
}

TEST(PngIo, WriteRejectsBadImagesAndUnwritablePaths) {
    Image bad = make_pattern(4, 4, 3);
    bad.pixels.pop_back();
    expect_error([&] { stipple::write_png("/tmp/stipple-bad.png", bad); }, "cannot write PNG");
    expect_error([] { stipple::write_png("/tmp/stipple-empty.png", Image{}); }, "cannot write PNG");
    const auto dir = stipple::test::temp_dir("png_unwritable");
    // A path whose "parent folder" is a regular file cannot be created.
    const std::string blocker = (dir / "file").string();
    std::ofstream(blocker) << "x";
    expect_error([&] { stipple::write_png(blocker + "/sub/out.png", make_pattern(2, 2, 1)); },
                 "cannot write PNG");
}
