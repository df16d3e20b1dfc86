// Numbers as text in a locale whose decimal point is a comma (de_DE.UTF-8, set both ways a
// program sets it: setlocale for C, std::locale::global for C++): everything grape writes is
// byte for byte what it writes in the "C" locale, and reads back to the same doubles. The
// portable paths of src/math/number_text.hpp (strtod and printf with a "C" locale object),
// which serve where <charconv> lacks double, are held to <charconv> here too. The locale
// comes from scripts/install-deps; without it the tests are skipped, saying so.
#include <grape/color.hpp>
#include <grape/config.hpp>
#include <grape/curve.hpp>
#include <grape/error.hpp>
#include <grape/path.hpp>
#include <grape/path_query.hpp>
#include <grape/timeline_layout.hpp>
#if GRAPE_TEST_SCENE
#include <grape/scene.hpp>
#include <grape/sprite_sheet_json.hpp>
#endif

#include "math/number_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <locale>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using grape::detail::NumberRead;

constexpr const char* german = "de_DE.UTF-8";

// The whole process in `name` (C and C++), as a program that honours its user's locale is.
bool use_locale(const char* name) {
    if (!std::setlocale(LC_ALL, name)) return false;
    try {
        std::locale::global(std::locale(name));
    } catch (const std::runtime_error&) {
        std::setlocale(LC_ALL, "C");
        return false;
    }
    return true;
}

void use_c_locale() {
    std::locale::global(std::locale::classic());
    std::setlocale(LC_ALL, "C");
}

// f() in the "C" locale and in German, for comparing byte for byte.
template <class F>
auto in_c_and_german(F f) {
    use_c_locale();
    auto c = f();
    if (!use_locale(german)) throw std::runtime_error("de_DE.UTF-8 went missing");
    auto de = f();
    return std::pair{std::move(c), std::move(de)};
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

class GermanLocale : public ::testing::Test {
protected:
    void SetUp() override {
        if (!use_locale(german)) {
            GTEST_SKIP() << "the locale de_DE.UTF-8 is not installed (scripts/install-deps generates it; or "
                            "localedef -i de_DE -f UTF-8 de_DE.UTF-8): the locale tests did not run";
        }
        // The premise: in this locale printf, strtod and streams do use a comma.
        ASSERT_STREQ(std::localeconv()->decimal_point, ",");
        std::ostringstream stream;
        stream << 0.5;
        ASSERT_EQ(stream.str(), "0,5");
    }
    void TearDown() override { use_c_locale(); }
};

TEST_F(GermanLocale, SvgPathDataReadsBackBitExact) {
    const grape::Path path = grape::parse_svg_path("M0.1 0.2 C1.5 2.25 3.125 4.0625 5.3 6.7 Q7.77 8.5 9.1 0.333 L-1.25e-3 12.5");
    const auto [c, de] = in_c_and_german([&] { return grape::svg_path_data(path); });
    EXPECT_EQ(de, c);
    EXPECT_NE(de.find("0.10000000000000001"), std::string::npos) << de;
    EXPECT_EQ(de.find(','), std::string::npos) << de;
    // Read back in German: the same path, to the bit.
    const grape::Path again = grape::parse_svg_path(de);
    EXPECT_EQ(grape::svg_path_data(again), de);
    for (const double u : {0.0, 0.125, 0.5, 0.875, 1.0}) {
        EXPECT_TRUE(same_bits(again.point(u).x, path.point(u).x)) << u;
        EXPECT_TRUE(same_bits(again.point(u).y, path.point(u).y)) << u;
    }
}

TEST_F(GermanLocale, CurveNamesWithNumbers) {
    const std::pair<const char*, const char*> names[] = {
        {"spring-duration(0.5,0.25)", "spring-duration(0.5,0.25,0)"},
        {"cubic-bezier(0.25,0.1,0.25,1)", "cubic-bezier(0.25,0.1,0.25,1)"},
        {"back-in(2.5)", "back-in(2.5)"},
        {"elastic-out(1.5,0.3)", "elastic-out(1.5,0.3)"},
        {"monotone(0,0,0.25,0.75,1,1)", "monotone(0,0,0.25,0.75,1,1)"},
        {"spring(170.5,26.25,1.5,-0.125)", "spring(170.5,26.25,1.5,-0.125)"},
    };
    for (const auto& name : names) {  // (clang 14 cannot capture a structured binding)
        const auto [c, de] = in_c_and_german([&] { return grape::to_string(grape::parse_curve(name.first)); });
        EXPECT_EQ(de, c) << name.first;
        EXPECT_EQ(de, name.second);
    }
    const grape::Curve css = grape::parse_curve("cubic-bezier(0.25,0.1,0.25,1)");
    const grape::Curve spring = grape::parse_curve("spring-duration(0.5,0.25)");
    use_c_locale();
    EXPECT_TRUE(same_bits(css(0.5), grape::parse_curve("cubic-bezier(0.25,0.1,0.25,1)")(0.5)));
    EXPECT_TRUE(same_bits(spring(0.5), grape::parse_curve("spring-duration(0.5,0.25)")(0.5)));
}

TEST_F(GermanLocale, ColourTextWithAlpha) {
    const auto [c, de] = in_c_and_german([] {
        const grape::Color half = grape::parse_color("rgba(255, 128, 0, 0.5)");
        const grape::Color spaced = grape::parse_color("rgb(0 128 255 / 12.5%)");
        return grape::to_css(half) + " " + grape::to_css(spaced) + " " + grape::to_css({0.2, 0.4, 0.6, 0.125});
    });
    EXPECT_EQ(de, c);
    EXPECT_EQ(de, "rgba(255, 128, 0, 0.5) rgba(0, 128, 255, 0.125) rgba(51, 102, 153, 0.125)");
    EXPECT_EQ(grape::parse_color("rgba(255, 128, 0, 0.5)").a, 0.5);
}

TEST_F(GermanLocale, TimelinePositionText) {
    const auto [c, de] = in_c_and_german([] {
        std::string text;
        for (const char* p : {"1.5", "0.1", ">+0.25", "<-=0.125", "+=0.5", "intro+1.75", "intro-=0.25"})
            text += grape::to_string(grape::parse_timeline_position(p)) + " ";
        return text + grape::to_string(grape::timeline_position_at(2.0 / 3.0));
    });
    EXPECT_EQ(de, c);
    EXPECT_NE(de.find("0.10000000000000001"), std::string::npos) << de;
    EXPECT_NE(de.find("0.66666666666666663"), std::string::npos) << de;
    EXPECT_EQ(grape::parse_timeline_position("intro-=0.25").offset, -0.25);
    EXPECT_EQ(grape::parse_timeline_position(grape::to_string(grape::timeline_position_at(0.1))).offset, 0.1);
}

TEST_F(GermanLocale, ErrorMessagesQuoteNumbersWithAPoint) {
    try {
        (void)grape::parse_curve("back-in(-0.5)");
        FAIL() << "a negative overshoot was taken";
    } catch (const grape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("(got -0.5)"), std::string::npos) << e.what();
    }
    EXPECT_EQ(grape::detail::number_text(0.1), "0.1");
    EXPECT_EQ(grape::detail::number_text(1e100), "1e+100");
}

#if GRAPE_TEST_SCENE
// Every scene in scenes/ and one written for this test: loaded and saved in German, byte for
// byte what the "C" locale gives.
TEST_F(GermanLocale, ScenesSaveAsInTheCLocale) {
    std::vector<std::string> texts;
    for (const auto& entry : std::filesystem::directory_iterator(GRAPE_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        texts.push_back(text.str());
    }
    ASSERT_GE(texts.size(), 5u);
    texts.push_back(R"json({
  "grape_scene": 1, "name": "numbers", "view": {"width": 320.5, "height": 200.25, "ticks": 0.125},
  "paths": [{"name": "p", "path": {"kind": "svg", "data": "M0.5 0.25 C10.125 0.75 20.0625 30.5 40.3 50.7"}}],
  "curves": [{"name": "s", "curve": "spring-duration(0.5,0.25)"}, {"name": "c", "curve": "cubic-bezier(0.25,0.1,0.25,1)"}],
  "animations": [{"name": "a", "path": "p", "curve": "s", "duration": 1.75, "delay": 0.1}],
  "properties": [{"name": "tint", "type": "color", "value": "rgba(255, 128, 0, 0.5)"}],
  "tweens": [{"property": "tint", "to": "rgba(0, 0, 255, 0.125)", "duration": 0.6, "curve": "c"}],
  "timelines": [{"name": "t", "children": [{"animation": "a"}, {"label": "x"}, {"gap": 0.35, "at": "x-=0.25"}]}]
})json");
    for (const std::string& text : texts) {
        const auto saved = in_c_and_german([&] { return grape::save_scene(grape::load_scene(text)); });
        EXPECT_EQ(saved.second, saved.first) << text.substr(0, 80);
        const auto again = in_c_and_german([&] { return grape::save_scene(grape::load_scene(saved.second)); });
        EXPECT_EQ(again.second, saved.second) << "saved in German, loaded and saved again";
    }
}

TEST_F(GermanLocale, SpriteSheetWithFractionalDurations) {
    const char* json = R"({"frames": [
  {"filename": "a", "frame": {"x": 0, "y": 0, "w": 8, "h": 8}, "rotated": false, "trimmed": false,
   "spriteSourceSize": {"x": 0, "y": 0, "w": 8, "h": 8}, "sourceSize": {"w": 8, "h": 8}, "duration": 100.5},
  {"filename": "b", "frame": {"x": 8, "y": 0, "w": 8, "h": 8}, "rotated": false, "trimmed": false,
   "spriteSourceSize": {"x": 0, "y": 0, "w": 8, "h": 8}, "sourceSize": {"w": 8, "h": 8}, "duration": 33.333333333333336}],
 "meta": {"app": "https://www.aseprite.org/", "version": "1.3", "image": "s.png", "size": {"w": 16, "h": 8},
          "frameTags": [{"name": "go", "from": 0, "to": 1, "direction": "pingpong", "repeat": "3"}]}})";
    const grape::SpriteSheet sheet = grape::load_sprite_sheet(json);
    EXPECT_EQ(sheet.frame(0).duration_ms, 100.5);
    EXPECT_EQ(sheet.frame(1).duration_ms, 100.0 / 3.0);
    EXPECT_EQ(sheet.clips()[0].repeat, 3);
    for (const grape::SheetJsonLayout layout : {grape::SheetJsonLayout::hash, grape::SheetJsonLayout::array}) {
        const auto [c, de] = in_c_and_german([&] { return grape::save_sprite_sheet(grape::load_sprite_sheet(json), layout); });
        EXPECT_EQ(de, c);
        const grape::SpriteSheet again = grape::load_sprite_sheet(de);
        EXPECT_EQ(again.frame(1).duration_ms, 100.0 / 3.0);
        EXPECT_EQ(again.clips()[0].repeat, 3);
    }
}
#endif

// --- the portable paths against <charconv> ---------------------------------------------------

// Doubles of every kind: random bits, short decimals, powers of two (where the doubles below
// are twice as dense as those above), integers past 2^53, subnormals, the extremes.
std::vector<double> test_doubles() {
    std::vector<double> values = {0.0, -0.0, 0.1, 0.5, 1.0, 100000.0, 1e21, 1e22, 123456789012345680000.0, 1e-7,
                                  5e-324, 2.2250738585072014e-308, std::numeric_limits<double>::max(), 9007199254740993.0,
                                  0.3, 2.0 / 3.0, -1.25e-3, 1.7976931348623157e308, 4.9406564584124654e-324};
    for (int e = -1074; e <= 1023; ++e) values.push_back(std::ldexp(1.0, e));
    std::mt19937_64 random(grape::testing::test_seed(20240611));
    for (int i = 0; i < 20000; ++i) {
        const double v = std::bit_cast<double>(random());
        if (std::isfinite(v)) values.push_back(v);
    }
    std::uniform_int_distribution<int> digits(0, 999999);
    for (int i = 0; i < 5000; ++i) values.push_back(digits(random) / 1000.0);
    return values;
}

TEST_F(GermanLocale, PortableWritingMatchesCharconv) {
    int differences = 0;
    for (const double v : test_doubles()) {
        const std::string shortest = grape::detail::number_text(v);
        if (grape::detail::portable::shortest_text(v) != shortest && ++differences < 10)
            ADD_FAILURE() << "shortest " << shortest << " vs " << grape::detail::portable::shortest_text(v);
        for (const int precision : {1, 3, 6, 17}) {
            if (grape::detail::portable::general_text(v, precision) != grape::detail::general_text(v, precision) &&
                ++differences < 10)
                ADD_FAILURE() << "%." << precision << "g of " << shortest;
        }
        for (const int digits : {0, 2, 3}) {
            if (grape::detail::portable::fixed_text(v, digits) != grape::detail::fixed_text(v, digits) && ++differences < 10)
                ADD_FAILURE() << "%." << digits << "f of " << shortest;
        }
        // Both read back exactly, whichever way this library reads.
        double back = 0.0;
        const NumberRead read = grape::detail::parse_double(shortest.data(), shortest.data() + shortest.size(), back);
        if ((read.ec != std::errc() || !same_bits(back, v)) && ++differences < 10) ADD_FAILURE() << "read " << shortest;
        const std::string g17 = grape::detail::general_text(v, 17);
        const NumberRead read17 = grape::detail::portable::parse_double(g17.data(), g17.data() + g17.size(), back);
        if ((read17.ec != std::errc() || !same_bits(back, v)) && ++differences < 10) ADD_FAILURE() << "read " << g17;
    }
    EXPECT_EQ(differences, 0);
    for (const double v : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
        EXPECT_EQ(grape::detail::portable::shortest_text(v), grape::detail::number_text(v));
        EXPECT_EQ(grape::detail::portable::general_text(v, 17), grape::detail::general_text(v, 17));
    }
    EXPECT_EQ(grape::detail::portable::shortest_text(std::nan("")), grape::detail::number_text(std::nan("")));
}

struct Case {
    std::string text;
    std::errc ec;
    std::size_t length;  // what was read
    double value;        // when read (value 7 stays 7 otherwise)
};

TEST_F(GermanLocale, PortableReadingIsFromChars) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Case> cases = {
        {"0.5", std::errc(), 3, 0.5},          {"-0", std::errc(), 2, -0.0},        {"1,5", std::errc(), 1, 1.0},
        {".5", std::errc(), 2, 0.5},           {"5.", std::errc(), 2, 5.0},         {"1e", std::errc(), 1, 1.0},
        {"1e+", std::errc(), 1, 1.0},          {"1E-2x", std::errc(), 4, 0.01},     {"0x1p3", std::errc(), 1, 0.0},
        {"inf", std::errc(), 3, inf},          {"-Infinity", std::errc(), 9, -inf}, {"infinit", std::errc(), 3, inf},
        {"4e-320", std::errc(), 6, 4e-320},    {"00012.50", std::errc(), 8, 12.5},  {"1e400", std::errc::result_out_of_range, 5, 7},
        {"-1e-400", std::errc::result_out_of_range, 7, 7}, {"0e-400", std::errc(), 6, 0.0},
        {"", std::errc::invalid_argument, 0, 7},   {".", std::errc::invalid_argument, 0, 7},
        {"+1", std::errc::invalid_argument, 0, 7}, {" 1", std::errc::invalid_argument, 0, 7},
        {"-", std::errc::invalid_argument, 0, 7},  {"e5", std::errc::invalid_argument, 0, 7},
        {"0.1000000000000000055511151231257827021181583404541015625000001", std::errc(), 63, 0.1},
        {"2.4703282292062328e-324", std::errc(), 23, 5e-324},  // just above half the least subnormal
    };
    for (const Case& k : cases) {
        double value = 7.0;
        const NumberRead read = grape::detail::portable::parse_double(k.text.data(), k.text.data() + k.text.size(), value);
        EXPECT_EQ(read.ec, k.ec) << k.text;
        EXPECT_EQ(static_cast<std::size_t>(read.ptr - k.text.data()), k.length) << k.text;
        EXPECT_TRUE(same_bits(value, k.value)) << k.text << " read as " << grape::detail::number_text(value);
        // The library's own reader (from_chars where it has double) agrees.
        double own = 7.0;
        const NumberRead own_read = grape::detail::parse_double(k.text.data(), k.text.data() + k.text.size(), own);
        EXPECT_EQ(own_read.ec, read.ec) << k.text;
        EXPECT_EQ(own_read.ptr, read.ptr) << k.text;
        EXPECT_TRUE(same_bits(own, value)) << k.text;
    }
    double nan = 0.0;
    const std::string text = "nan(chars_1)x";
    const NumberRead read = grape::detail::portable::parse_double(text.data(), text.data() + text.size(), nan);
    EXPECT_EQ(read.ec, std::errc());
    EXPECT_EQ(read.ptr, text.data() + 12);
    EXPECT_TRUE(std::isnan(nan));
    // Stops at last, even where the text goes on (strtod alone would read "12").
    const std::string digits = "12";
    double one = 0.0;
    EXPECT_EQ(grape::detail::portable::parse_double(digits.data(), digits.data() + 1, one).ptr, digits.data() + 1);
    EXPECT_EQ(one, 1.0);
}

}  // namespace
