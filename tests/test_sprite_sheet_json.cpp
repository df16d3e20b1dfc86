// Tests for the sprite-sheet JSON readers (grape/sprite_sheet_json.hpp): grape's own sheet in
// Aseprite's format in both layouts (tests/data/sprites, drawn and written by
// make_sprite_sheet from the format's documentation), TexturePacker's hash and array layouts
// with trimmed and rotated frames, and errors that name the JSON pointer.
#include <grape/error.hpp>
#include <grape/sprite_sheet_json.hpp>

#include "clip_reference.hpp"
#include "error_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#ifndef GRAPE_SPRITE_DATA
#error "GRAPE_SPRITE_DATA must name tests/data/sprites"
#endif

namespace {

using grape::ClipDirection;
using grape::ClipEvent;
using grape::ClipPlayer;
using grape::SpriteSheet;
using grape::testing::expect_error;
using grape::testing::Reference;
using grape::testing::RefEvent;

const std::string data = GRAPE_SPRITE_DATA;

void expect_same_sheet(const SpriteSheet& a, const SpriteSheet& b) {
    EXPECT_EQ(a.image(), b.image());
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    ASSERT_EQ(a.frame_count(), b.frame_count());
    for (std::size_t k = 0; k < a.frame_count(); ++k) {
        const grape::SpriteFrame &f = a.frame(k), &g = b.frame(k);
        EXPECT_EQ(f.name, g.name);
        EXPECT_EQ(f.rect, g.rect);
        EXPECT_EQ(f.rotated, g.rotated);
        EXPECT_EQ(f.offset_x, g.offset_x);
        EXPECT_EQ(f.offset_y, g.offset_y);
        EXPECT_EQ(f.source_width, g.source_width);
        EXPECT_EQ(f.source_height, g.source_height);
        EXPECT_EQ(f.duration_ms, g.duration_ms);
        EXPECT_EQ(f.pivot.x, g.pivot.x);
        EXPECT_EQ(f.pivot.y, g.pivot.y);
    }
    ASSERT_EQ(a.clips().size(), b.clips().size());
    for (std::size_t k = 0; k < a.clips().size(); ++k) {
        EXPECT_EQ(a.clips()[k].name, b.clips()[k].name);
        EXPECT_EQ(a.clips()[k].from, b.clips()[k].from);
        EXPECT_EQ(a.clips()[k].to, b.clips()[k].to);
        EXPECT_EQ(a.clips()[k].direction, b.clips()[k].direction);
        EXPECT_EQ(a.clips()[k].repeat, b.clips()[k].repeat);
    }
    ASSERT_EQ(a.slices().size(), b.slices().size());
    for (std::size_t k = 0; k < a.slices().size(); ++k) {
        EXPECT_EQ(a.slices()[k].name, b.slices()[k].name);
        ASSERT_EQ(a.slices()[k].keys.size(), b.slices()[k].keys.size());
    }
}

TEST(SpriteSheetJson, OurSheetReadsTheSameInBothLayouts) {
    const SpriteSheet hash = grape::load_sprite_sheet_file(data + "/grape_sheet.json");
    const SpriteSheet array = grape::load_sprite_sheet_file(data + "/grape_sheet_array.json");
    expect_same_sheet(hash, array);
    EXPECT_EQ(hash.image(), "grape_sheet.png");
    EXPECT_EQ(grape::sprite_sheet_image_path(hash, data + "/grape_sheet.json"),
              std::filesystem::path(data) / "grape_sheet.png");
    ASSERT_EQ(hash.frame_count(), 8u);
    // Frames in file order with Aseprite's keys and uneven durations.
    const double durations[] = {100, 150, 50, 200, 80, 120, 60, 240};
    for (std::size_t k = 0; k < 8; ++k) {
        EXPECT_EQ(hash.frame(k).name, "grape " + std::to_string(k) + ".aseprite");
        EXPECT_EQ(hash.frame(k).duration_ms, durations[k]);
        EXPECT_TRUE(hash.frame(k).trimmed());
        EXPECT_EQ(hash.frame(k).source_width, 48);
    }
    // Tags of every direction, with and without repeats ("repeat" is a string in the file).
    ASSERT_EQ(hash.clips().size(), 7u);
    EXPECT_EQ(hash.clips()[hash.clip_index("rewind")].direction, ClipDirection::reverse);
    EXPECT_EQ(hash.clips()[hash.clip_index("hop")].direction, ClipDirection::ping_pong);
    EXPECT_EQ(hash.clips()[hash.clip_index("hop")].repeat, 3);
    EXPECT_EQ(hash.clips()[hash.clip_index("sway")].direction, ClipDirection::ping_pong_reverse);
    // The feet slice's pivot (bounds + pivot), in the untrimmed image, changes at frame 4.
    EXPECT_EQ(hash.frame(0).pivot.x, 24.0);
    EXPECT_EQ(hash.frame(0).pivot.y, 44.0);
    EXPECT_EQ(hash.frame(5).pivot.x, 24.0);
    ASSERT_NE(hash.slice_key("hit", 7), nullptr);
    EXPECT_FALSE(hash.slice_key("hit", 7)->has_pivot);
    // Saved and read again, nothing changes.
    expect_same_sheet(grape::load_sprite_sheet(grape::save_sprite_sheet(hash, grape::SheetJsonLayout::array)), hash);
}

// Every clip of the sheet, forwards and (when it ends) backwards, at rates m/8 with 1/64 s
// steps: frame by frame and event by event as the reference model has it.
TEST(SpriteSheetJson, OurSheetPlaysFrameExactAgainstTheReference) {
    const SpriteSheet sheet = grape::load_sprite_sheet_file(data + "/grape_sheet_array.json");
    int checked = 0;
    for (std::size_t c = 0; c < sheet.clips().size(); ++c) {
        for (std::int64_t m : {1, 3, 8, 13, 40, 200, -1, -5, -8, -77}) {
            const bool backward = m < 0;
            if (backward && sheet.clips()[c].repeat == 0) continue;
            const std::int64_t scale = 8 * 64;                     // times are N / 512 ms
            const std::int64_t per_step = (backward ? -m : m) * 1000;  // |m/8|·(1/64 s)·1000·512
            Reference ref(sheet, sheet.clips()[c], 2 + 600 * per_step / scale / 50, backward);
            ClipPlayer player(sheet, c, {.rate = static_cast<double>(m) / 8});
            std::vector<RefEvent> got;
            player.on_event([&](const ClipEvent& e) { got.push_back({e.kind, e.frame, e.pass}); });
            ASSERT_EQ(player.frame(), ref.frame());
            for (int k = 1; k <= 600 && !ref.done; ++k) {
                got.clear();
                player.advance(1.0 / 64);
                ASSERT_EQ(got, ref.play_to(per_step * k, scale)) << sheet.clips()[c].name << " rate " << m << "/8 step " << k;
                ASSERT_EQ(player.frame(), ref.frame());
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 7 * 6 + 3 * 4);
}

// TexturePacker's JSON (Hash), written from its documentation: a trimmed frame, a rotated one
// (stored turned 90° clockwise, its w and h the upright sprite's) and pivots as fractions.
const char* texture_packer_hash = R"({"frames": {
  "hero/run_01.png": {"frame": {"x": 2, "y": 2, "w": 30, "h": 40}, "rotated": false, "trimmed": true,
                      "spriteSourceSize": {"x": 5, "y": 8, "w": 30, "h": 40}, "sourceSize": {"w": 40, "h": 48},
                      "pivot": {"x": 0.5, "y": 1}},
  "hero/run_02.png": {"frame": {"x": 34, "y": 2, "w": 36, "h": 20}, "rotated": true, "trimmed": true,
                      "spriteSourceSize": {"x": 2, "y": 14, "w": 36, "h": 20}, "sourceSize": {"w": 40, "h": 48},
                      "pivot": {"x": 0.25, "y": 0.5}},
  "coin.png": {"frame": {"x": 2, "y": 44, "w": 16, "h": 16}, "rotated": false, "trimmed": false,
               "spriteSourceSize": {"x": 0, "y": 0, "w": 16, "h": 16}, "sourceSize": {"w": 16, "h": 16}}},
 "meta": {"app": "https://www.codeandweb.com/texturepacker", "version": "1.0", "image": "atlas.png",
          "format": "RGBA8888", "size": {"w": 64, "h": 64}, "scale": "1", "smartupdate": "$x$"}})";

TEST(SpriteSheetJson, TexturePackerHashAndArrayWithTrimmedAndRotatedFrames) {
    const SpriteSheet hash = grape::load_sprite_sheet(texture_packer_hash);
    ASSERT_EQ(hash.frame_count(), 3u);
    EXPECT_EQ(hash.frame(0).name, "hero/run_01.png");  // file order, not key order
    EXPECT_EQ(hash.frame(2).name, "coin.png");
    const grape::SpriteFrame& run = hash.frame(0);
    EXPECT_TRUE(run.trimmed());
    EXPECT_EQ(run.offset_x, 5);
    EXPECT_EQ(run.offset_y, 8);
    EXPECT_EQ(run.pivot.x, 20.0);  // 0.5 · 40
    EXPECT_EQ(run.pivot.y, 48.0);
    EXPECT_EQ(run.duration_ms, 100.0);  // no durations in TexturePacker: Aseprite's default
    const grape::SpriteFrame& turned = hash.frame(1);
    EXPECT_TRUE(turned.rotated);
    EXPECT_EQ(turned.rect, (grape::FrameRect{34, 2, 20, 36}));  // the region on the sheet
    EXPECT_EQ(turned.width(), 36);
    EXPECT_EQ(turned.height(), 20);
    EXPECT_EQ(turned.pivot.x, 10.0);
    EXPECT_FALSE(hash.frame(2).trimmed());
    EXPECT_TRUE(hash.clips().empty());
    // The same atlas as JSON (Array): frames carry their names as "filename".
    std::string array = R"({"frames": [)";
    array += R"({"filename": "hero/run_01.png", "frame": {"x": 2, "y": 2, "w": 30, "h": 40}, "rotated": false, "trimmed": true,
                 "spriteSourceSize": {"x": 5, "y": 8, "w": 30, "h": 40}, "sourceSize": {"w": 40, "h": 48}, "pivot": {"x": 0.5, "y": 1}},)";
    array += R"({"filename": "hero/run_02.png", "frame": {"x": 34, "y": 2, "w": 36, "h": 20}, "rotated": true, "trimmed": true,
                 "spriteSourceSize": {"x": 2, "y": 14, "w": 36, "h": 20}, "sourceSize": {"w": 40, "h": 48}, "pivot": {"x": 0.25, "y": 0.5}},)";
    array += R"({"filename": "coin.png", "frame": {"x": 2, "y": 44, "w": 16, "h": 16}, "rotated": false, "trimmed": false,
                 "spriteSourceSize": {"x": 0, "y": 0, "w": 16, "h": 16}, "sourceSize": {"w": 16, "h": 16}}],)";
    array += R"("meta": {"image": "atlas.png", "size": {"w": 64, "h": 64}, "scale": "1"}})";
    expect_same_sheet(grape::load_sprite_sheet(array), hash);
}

// Aseprite's exporter (src/app/doc_exporter.cpp) with --inner-padding 1 --border-padding 2
// --shape-padding 3 --trim --sheet-type horizontal --filename-format {title}_{frame}: each cell
// is the trimmed size plus 1 on every side, written as `frame`; the trimmed pixels' place in
// the 24x40 sprite is spriteSourceSize. Cells start at the border (2, 2) and follow each other
// with 3 pixels between: x = 2, 2 + 18 + 3 = 23, 23 + 20 + 3 = 46; the sheet is the cells'
// bounds plus the border, 46 + 22 + 2 = 70 by 2 + 35 + 2 = 39. The pixels are drawn at the cell
// plus the inner padding.
const char* aseprite_padded = R"({ "frames": {
   "idle_0": { "frame": { "x": 2, "y": 2, "w": 18, "h": 33 }, "rotated": false, "trimmed": true,
    "spriteSourceSize": { "x": 4, "y": 5, "w": 16, "h": 31 }, "sourceSize": { "w": 24, "h": 40 }, "duration": 100 },
   "idle_1": { "frame": { "x": 23, "y": 2, "w": 20, "h": 32 }, "rotated": false, "trimmed": true,
    "spriteSourceSize": { "x": 3, "y": 6, "w": 18, "h": 30 }, "sourceSize": { "w": 24, "h": 40 }, "duration": 120 },
   "idle_2": { "frame": { "x": 46, "y": 2, "w": 22, "h": 35 }, "rotated": false, "trimmed": true,
    "spriteSourceSize": { "x": 2, "y": 4, "w": 20, "h": 33 }, "sourceSize": { "w": 24, "h": 40 }, "duration": 80 }
 },
 "meta": { "app": "https://www.aseprite.org/", "version": "1.3.7-x64", "image": "idle.png", "format": "RGBA8888",
  "size": { "w": 70, "h": 39 }, "scale": "1",
  "frameTags": [ { "name": "idle", "from": 0, "to": 2, "direction": "pingpong", "color": "#000000ff" } ],
  "layers": [ { "name": "Layer 1", "opacity": 255, "blendMode": "normal" } ], "slices": [ ] }
})";

TEST(SpriteSheetJson, AsepriteInnerBorderAndShapePadding) {
    const SpriteSheet sheet = grape::load_sprite_sheet(aseprite_padded);
    ASSERT_EQ(sheet.frame_count(), 3u);
    // Pixels at the cell + 1, of spriteSourceSize's size; offsets and sizes as written.
    const grape::FrameRect pixels[] = {{3, 3, 16, 31}, {24, 3, 18, 30}, {47, 3, 20, 33}};
    const int offsets[][2] = {{4, 5}, {3, 6}, {2, 4}};
    for (std::size_t k = 0; k < 3; ++k) {
        SCOPED_TRACE(k);
        const grape::SpriteFrame& f = sheet.frame(k);
        EXPECT_EQ(f.rect, pixels[k]);
        EXPECT_EQ(f.offset_x, offsets[k][0]);
        EXPECT_EQ(f.offset_y, offsets[k][1]);
        EXPECT_EQ(f.source_width, 24);
        EXPECT_EQ(f.source_height, 40);
        EXPECT_TRUE(f.trimmed());
    }
    EXPECT_EQ(sheet.clips()[0].direction, ClipDirection::ping_pong);
    EXPECT_EQ(sheet.scale(), 1.0);
    // Written back without padding (frame = the pixels), it reads the same.
    expect_same_sheet(grape::load_sprite_sheet(grape::save_sprite_sheet(sheet, grape::SheetJsonLayout::hash)), sheet);

    // Untrimmed with --inner-padding 2 (array layout): the 24x40 sprite in a 28x44 cell at the
    // border (2, 2), its pixels at (4, 4); spriteSourceSize is the whole sprite.
    const SpriteSheet untrimmed = grape::load_sprite_sheet(R"({"frames": [
        {"filename": "idle_0", "frame": {"x": 2, "y": 2, "w": 28, "h": 44}, "rotated": false, "trimmed": false,
         "spriteSourceSize": {"x": 0, "y": 0, "w": 24, "h": 40}, "sourceSize": {"w": 24, "h": 40}, "duration": 100}],
        "meta": {"size": {"w": 32, "h": 48}, "scale": "1"}})");
    EXPECT_EQ(untrimmed.frame(0).rect, (grape::FrameRect{4, 4, 24, 40}));
    EXPECT_FALSE(untrimmed.frame(0).trimmed());
}

TEST(SpriteSheetJson, UnequalPaddingIsAnErrorNamingTheField) {
    // A cell 2p larger on one axis only, larger by an odd number, or smaller than the pixels:
    // no padding Aseprite writes.
    for (const char* sizes : {R"("w": 18, "h": 32)", R"("w": 17, "h": 32)", R"("w": 14, "h": 29)"}) {
        SCOPED_TRACE(sizes);
        const std::string text = std::string(R"({"frames": {"idle_0": {"frame": {"x": 0, "y": 0, )") + sizes +
                                 R"(}, "spriteSourceSize": {"x": 4, "y": 5, "w": 16, "h": 31}, "sourceSize": {"w": 24, "h": 40}}},
                                     "meta": {"size": {"w": 64, "h": 64}}})";
        expect_error([&] { grape::load_sprite_sheet(text); },
                     {"sprite sheet: /frames/idle_0/spriteSourceSize: size 16x31 differs from the frame's", "inner padding"});
    }
}

// TexturePacker's "crop, keep position" (JSON (Array)): the crop is the sprite, so sourceSize
// is the crop's size and `trimmed` false, and spriteSourceSize's x, y keep where the crop sat
// in the art; the pivot is a fraction of the crop. Here a 192x192 art with its pivot at the
// center (96, 96): cropped to 114x113 at (37, 79), the pivot is ((96 − 37)/114, (96 − 79)/113)
// = (0.517544, 0.150442) to TexturePacker's six digits. A second crop sits left of and above
// the art's origin, at (−3, −2). The sheet is exported at half scale ("scale": "0.5").
const char* texture_packer_crop_keep_position = R"({"frames": [
  {"filename": "mole_hit_17.png", "frame": {"x": 1, "y": 1, "w": 114, "h": 113}, "rotated": false, "trimmed": false,
   "spriteSourceSize": {"x": 37, "y": 79, "w": 114, "h": 113}, "sourceSize": {"w": 114, "h": 113},
   "pivot": {"x": 0.517544, "y": 0.150442}},
  {"filename": "spark.png", "frame": {"x": 116, "y": 1, "w": 40, "h": 30}, "rotated": false, "trimmed": false,
   "spriteSourceSize": {"x": -3, "y": -2, "w": 40, "h": 30}, "sourceSize": {"w": 40, "h": 30},
   "pivot": {"x": 0.5, "y": 0.5}}],
 "meta": {"app": "https://www.codeandweb.com/texturepacker", "version": "1.1", "image": "moles.png",
          "format": "RGBA8888", "size": {"w": 160, "h": 128}, "scale": "0.5", "smartupdate": "$TexturePacker:SmartUpdate:0$",
          "related_multi_packs": ["moles-1.json"]}})";

TEST(SpriteSheetJson, TexturePackerCropKeepPositionAndScale) {
    const SpriteSheet sheet = grape::load_sprite_sheet(texture_packer_crop_keep_position);
    const grape::SpriteFrame& mole = sheet.frame(0);
    EXPECT_FALSE(mole.trimmed());
    EXPECT_EQ(mole.rect, (grape::FrameRect{1, 1, 114, 113}));
    EXPECT_EQ(mole.offset_x, 37);
    EXPECT_EQ(mole.offset_y, 79);
    // The pivot back where it was in the art: to within the six digits' rounding, 5e-7 of the
    // crop's size.
    EXPECT_NEAR(mole.pivot.x, 96.0, 5e-7 * 114);
    EXPECT_NEAR(mole.pivot.y, 96.0, 5e-7 * 113);
    const grape::SpriteFrame& spark = sheet.frame(1);
    EXPECT_EQ(spark.offset_x, -3);
    EXPECT_EQ(spark.offset_y, -2);
    EXPECT_EQ(spark.pivot.x, 17.0);  // −3 + 0.5·40
    EXPECT_EQ(spark.pivot.y, 13.0);  // −2 + 0.5·30
    // The sheet's pixels are half the art's.
    EXPECT_EQ(sheet.scale(), 0.5);
    // Written back (in Aseprite's form, which has no frame pivots) the offsets and the scale stay.
    const SpriteSheet again = grape::load_sprite_sheet(grape::save_sprite_sheet(sheet, grape::SheetJsonLayout::array));
    EXPECT_EQ(again.frame(1).offset_x, -3);
    EXPECT_EQ(again.frame(1).offset_y, -2);
    EXPECT_EQ(again.scale(), 0.5);
    // Trimmed pixels (smaller than sourceSize) must still lie inside the untrimmed image.
    expect_error([] {
        grape::load_sprite_sheet(R"({"frames": [{"frame": {"x": 0, "y": 0, "w": 10, "h": 10},
            "spriteSourceSize": {"x": -1, "y": 0, "w": 10, "h": 10}, "sourceSize": {"w": 12, "h": 12}}],
            "meta": {"size": {"w": 16, "h": 16}}})");
    }, {"sprite sheet: /frames/0/spriteSourceSize: puts the trimmed 10x10 pixels at (-1, 0), outside the 12x12 sourceSize"});
}

TEST(SpriteSheetJson, ScaleAndAnchor) {
    const auto with_meta = [](const std::string& extra) {
        return R"({"frames": [{"frame": {"x": 0, "y": 0, "w": 8, "h": 4}, "anchor": {"x": 0.25, "y": 1}}],
                   "meta": {"size": {"w": 8, "h": 8})" + extra + "}}";
    };
    EXPECT_EQ(grape::load_sprite_sheet(with_meta("")).scale(), 1.0);
    EXPECT_EQ(grape::load_sprite_sheet(with_meta(R"(, "scale": "2")")).scale(), 2.0);
    EXPECT_EQ(grape::load_sprite_sheet(with_meta(R"(, "scale": 0.25)")).scale(), 0.25);
    // PixiJS's `anchor` is TexturePacker's pivot: a fraction of the sprite's size.
    const SpriteSheet anchored = grape::load_sprite_sheet(with_meta(""));
    EXPECT_EQ(anchored.frame(0).pivot.x, 2.0);
    EXPECT_EQ(anchored.frame(0).pivot.y, 4.0);
    expect_error([&] { grape::load_sprite_sheet(with_meta(R"(, "scale": "half")")); },
                 {"sprite sheet: /meta/scale: expected a number as text, like \"0.5\" (got \"half\")"});
    expect_error([&] { grape::load_sprite_sheet(with_meta(R"(, "scale": "0")")); }, {"sprite sheet: /meta/scale: must be positive (got 0)"});
    expect_error([&] { grape::load_sprite_sheet(with_meta(R"(, "scale": -1)")); }, {"sprite sheet: /meta/scale: must be positive (got -1)"});
    expect_error([&] { grape::load_sprite_sheet(with_meta(R"(, "scale": true)")); }, {"sprite sheet: /meta/scale: expected a number"});
}

// Aseprite's user data and layer list (--list-layers, --list-slices): tags and slices carry a
// colour and text, slice keys a 9-slice center; the layers name groups, opacity, blend mode
// and cels. None of it changes the frames; the slices are read.
TEST(SpriteSheetJson, AsepriteUserDataLayersAndSliceCenters) {
    const SpriteSheet sheet = grape::load_sprite_sheet(R"({ "frames": [
       { "filename": "button 0.aseprite", "frame": { "x": 0, "y": 0, "w": 32, "h": 16 }, "rotated": false, "trimmed": false,
         "spriteSourceSize": { "x": 0, "y": 0, "w": 32, "h": 16 }, "sourceSize": { "w": 32, "h": 16 }, "duration": 100 },
       { "filename": "button 1.aseprite", "frame": { "x": 32, "y": 0, "w": 32, "h": 16 }, "rotated": false, "trimmed": false,
         "spriteSourceSize": { "x": 0, "y": 0, "w": 32, "h": 16 }, "sourceSize": { "w": 32, "h": 16 }, "duration": 100 } ],
     "meta": { "app": "https://www.aseprite.org/", "version": "1.3.7-x64", "image": "button.png", "format": "I8",
      "size": { "w": 64, "h": 16 }, "scale": "1",
      "frameTags": [ { "name": "press", "from": 0, "to": 1, "direction": "forward", "repeat": "1", "color": "#fe5b59ff", "data": "once" } ],
      "layers": [ { "name": "ui" }, { "name": "face", "group": "ui", "opacity": 128, "blendMode": "multiply", "color": "#00ff00ff",
                    "data": "shade", "cels": [{ "frame": 1, "opacity": 64, "zIndex": 1, "data": "pressed" }] } ],
      "slices": [ { "name": "nine", "color": "#0000ffff", "data": "frame",
                    "keys": [{ "frame": 0, "bounds": {"x": 0, "y": 0, "w": 32, "h": 16 }, "center": {"x": 4, "y": 4, "w": 24, "h": 8 } }] } ] }
    })");
    ASSERT_EQ(sheet.frame_count(), 2u);
    EXPECT_EQ(sheet.clips()[0].repeat, 1);
    ASSERT_EQ(sheet.slices().size(), 1u);
    EXPECT_EQ(sheet.slices()[0].keys[0].bounds, (grape::FrameRect{0, 0, 32, 16}));
    EXPECT_FALSE(sheet.slices()[0].keys[0].has_pivot);
    EXPECT_EQ(sheet.frame(1).pivot.x, 0.0);
}

// Several sprites on one sheet (aseprite -b hero.aseprite slime.aseprite coin.aseprite --sheet
// --list-tags --tagname-format {title}/{tag}): frames get Aseprite's default names for several
// files, "{title} {frame}.{extension}" ("{title}.{extension}" for one frame), and each
// sprite's tags count that sprite's frames from 0. With the title in the tag names the sheet
// says which sprite a tag is in: slime's frames 0–1 are sheet frames 4–5, coin's 0 is 6.
std::string packed_sheet(const std::string& tags) {
    std::string frames;
    int x = 0;
    for (const char* name : {"hero 0", "hero 1", "hero 2", "hero 3", "slime 0", "slime 1", "coin"}) {
        if (!frames.empty()) frames += ", ";
        frames += "\"" + std::string(name) + ".aseprite\": {\"frame\": {\"x\": " + std::to_string(x) +
                  ", \"y\": 0, \"w\": 8, \"h\": 8}, \"duration\": 100}";
        x += 8;
    }
    return "{\"frames\": {" + frames + "}, \"meta\": {\"size\": {\"w\": 56, \"h\": 8}, \"frameTags\": " + tags + "}}";
}

TEST(SpriteSheetJson, AsepriteTagsCountEachPackedSpritesFrames) {
    const SpriteSheet sheet = grape::load_sprite_sheet(packed_sheet(R"([
        {"name": "hero/idle", "from": 0, "to": 1, "direction": "forward"},
        {"name": "hero/run", "from": 2, "to": 3, "direction": "forward"},
        {"name": "slime/hop", "from": 0, "to": 1, "direction": "pingpong"},
        {"name": "coin/spin", "from": 0, "to": 0, "direction": "forward"},
        {"name": "all", "from": 0, "to": 6, "direction": "forward"}])"));
    const std::size_t expected[][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 6}, {0, 6}};
    ASSERT_EQ(sheet.clips().size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        SCOPED_TRACE(sheet.clips()[k].name);
        EXPECT_EQ(sheet.clips()[k].from, expected[k][0]);
        EXPECT_EQ(sheet.clips()[k].to, expected[k][1]);
    }
    // Saved, the tags count their sprites' frames again, and read back the same.
    const std::string saved = grape::save_sprite_sheet(sheet, grape::SheetJsonLayout::hash);
    const std::size_t hop = saved.find("\"slime/hop\"");
    ASSERT_NE(hop, std::string::npos);
    const std::string hop_tag = saved.substr(hop, saved.find('}', hop) - hop);
    EXPECT_NE(hop_tag.find("\"from\": 0,"), std::string::npos) << hop_tag;
    EXPECT_NE(hop_tag.find("\"to\": 1,"), std::string::npos) << hop_tag;
    expect_same_sheet(grape::load_sprite_sheet(saved), sheet);
    // A clip given in code that names a sprite but leaves its frames cannot be written so.
    grape::SpriteSheetDef def{.width = sheet.width(), .height = sheet.height(), .frames = {sheet.frames().begin(), sheet.frames().end()},
                              .clips = {{.name = "slime/all", .from = 0, .to = 6}}};
    expect_error([&] { grape::save_sprite_sheet(SpriteSheet(def), grape::SheetJsonLayout::array); },
                 {"save_sprite_sheet: clip 'slime/all' names sprite 'slime' (sheet frames 4 to 5) but plays frames 0 to 6"});
    // A tag past its own sprite's frames is an error naming the sprite.
    expect_error([] { grape::load_sprite_sheet(packed_sheet(R"([{"name": "slime/hop", "from": 0, "to": 2}])")); },
                 {"sprite sheet: /meta/frameTags/0/to: 2 is past the last frame (frame count 2) of sprite \"slime\" (sheet frames 4 to 5)"});
    // Frames not named so (one sprite, or names of the user's own format): tags are sheet frames.
    const SpriteSheet single = grape::load_sprite_sheet(R"({"frames": {"hero 0.aseprite": {"frame": {"x": 0, "y": 0, "w": 8, "h": 8}},
        "hero 1.aseprite": {"frame": {"x": 8, "y": 0, "w": 8, "h": 8}}},
        "meta": {"size": {"w": 16, "h": 8}, "frameTags": [{"name": "hero/b", "from": 1, "to": 1}]}})");
    EXPECT_EQ(single.clips()[0].from, 1u);
}

// A small valid Aseprite sheet, and the same with one value broken: the error names its pointer.
std::string sheet_with(const std::string& frame1, const std::string& tags, const std::string& size = R"({"w": 32, "h": 16})") {
    return R"({"frames": {"a": {"frame": {"x": 0, "y": 0, "w": 16, "h": 16}, "duration": 100}, "b/c": )" + frame1 +
           R"(}, "meta": {"size": )" + size + R"(, "frameTags": )" + tags + "}}";
}

TEST(SpriteSheetJson, ErrorsNameTheJsonPointer) {
    const std::string good_frame = R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "duration": 50})";
    const std::string good_tags = R"([{"name": "t", "from": 0, "to": 1, "direction": "pingpong", "repeat": "2"}])";
    EXPECT_EQ(grape::load_sprite_sheet(sheet_with(good_frame, good_tags)).clips()[0].repeat, 2);
    using F = std::vector<std::string>;
    const std::vector<std::pair<std::string, F>> cases = {
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "duration": 0})", good_tags),
         {"sprite sheet: /frames/b~1c/duration: must be positive", "got 0"}},
        {sheet_with(R"({"frame": {"x": 20, "y": 0, "w": 16, "h": 16}})", good_tags),
         {"/frames/b~1c/frame: at (20, 0) size 16x16 leaves the 32x16 sheet"}},
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16.5, "h": 16}})", good_tags), {"/frames/b~1c/frame/w", "whole number"}},
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "rotated": 1})", good_tags),
         {"/frames/b~1c/rotated: expected true or false"}},
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "spriteSourceSize": {"x": 4, "y": 0, "w": 16, "h": 16}, "sourceSize": {"w": 18, "h": 16}})", good_tags),
         {"/frames/b~1c/spriteSourceSize", "outside the 18x16 sourceSize"}},
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "spriteSourceSize": {"x": -1, "y": 0, "w": 15, "h": 16}, "sourceSize": {"w": 16, "h": 16}})", good_tags),
         {"/frames/b~1c/spriteSourceSize: size 15x16 differs from the frame's 16x16 other than by an inner padding"}},
        {sheet_with(R"({"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "spriteSourceSize": {"x": 0, "y": 0, "w": 8, "h": 16}})", good_tags),
         {"/frames/b~1c/spriteSourceSize: size 8x16 differs from the frame's 16x16"}},
        {sheet_with(good_frame, R"([{"name": "t", "from": 0, "to": 2}])"), {"/meta/frameTags/0/to: 2 is past the last frame (frame count 2)"}},
        {sheet_with(good_frame, R"([{"name": "t", "from": 1, "to": 0}])"), {"/meta/frameTags/0/to: 0 is before from (1)"}},
        {sheet_with(good_frame, R"([{"name": "t", "from": 0, "to": 1, "direction": "backward"}])"),
         {"/meta/frameTags/0/direction: unknown direction \"backward\"", "pingpong_reverse"}},
        {sheet_with(good_frame, R"([{"name": "t", "from": 0, "to": 1, "repeat": "-1"}])"), {"/meta/frameTags/0/repeat", "whole number >= 0"}},
        {sheet_with(good_frame, R"([{"from": 0, "to": 1}])"), {"/meta/frameTags/0: missing field \"name\""}},
        {sheet_with(good_frame, "{}"), {"/meta/frameTags: expected an array, got an object"}},
        {sheet_with(good_frame, good_tags, R"({"w": 0, "h": 16})"), {"/meta/size/w: must lie in [1, "}},
        {R"({"frames": [], "meta": {"size": {"w": 8, "h": 8}}})", {"/frames: a sheet needs at least one frame"}},
        {R"({"frames": 3, "meta": {"size": {"w": 8, "h": 8}}})", {"/frames: expected an object (hash layout) or an array"}},
        {R"({"frames": []})", {"sprite sheet: /: missing field \"meta\""}},
        {R"({"frames": [{"frame": {"x": 0, "y": 0, "w": 8, "h": 8}}], "meta": {"size": {"w": 8, "h": 8},
             "slices": [{"name": "s", "keys": [{"frame": 3, "bounds": {"x": 0, "y": 0, "w": 1, "h": 1}}]}]}})",
         {"/meta/slices/0/keys/0/frame: 3 is past the last frame"}},
        {R"({"frames": [}")", {"sprite sheet: JSON syntax error at byte"}},
    };
    for (const auto& broken : cases) {
        const std::string message = grape::testing::error_text([&] { grape::load_sprite_sheet(broken.first); });
        for (const std::string& fragment : broken.second) EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
    expect_error([] { grape::load_sprite_sheet_file(data + "/none.json"); }, {"cannot read", "none.json: no such file"});
    // The hash layout needs frame names to key by.
    const SpriteSheet unnamed({.width = 8, .height = 8, .frames = {{.rect = {0, 0, 8, 8}}}});
    expect_error([&] { grape::save_sprite_sheet(unnamed, grape::SheetJsonLayout::hash); }, {"unique, non-empty frame names"});
}

}  // namespace
