// Writes grape's own test and demo sprite sheet (the catalogue's grape_packed_sheet, drawn by
// scenes/sprite_sheets.cpp) as Aseprite would export it with trimming on: grape_sheet.png,
// grape_sheet.json (hash layout) and grape_sheet_array.json (array layout). No third-party art.
//
//   make_sprite_sheet OUT_DIR            writes the three files
//   make_sprite_sheet --check DIR        exits 1 unless DIR's files equal what it would write
#include "sprite_sheets.hpp"

#include <grape/error.hpp>
#include <grape/render.hpp>
#include <grape/sprite_sheet_json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const bool check = argc == 3 && std::string(argv[1]) == "--check";
        if (argc != 2 && !check) {
            std::fprintf(stderr, "usage: make_sprite_sheet OUT_DIR | make_sprite_sheet --check DIR\n");
            return 2;
        }
        const std::filesystem::path dir = argv[argc - 1];
        const grape::scenes::DrawnSheet drawn = grape::scenes::grape_packed_sheet();
        const std::string hash = grape::save_sprite_sheet(drawn.sheet, grape::SheetJsonLayout::hash);
        const std::string array = grape::save_sprite_sheet(drawn.sheet, grape::SheetJsonLayout::array);
        if (!check) {
            drawn.image.write_png(dir / "grape_sheet.png");
            std::ofstream(dir / "grape_sheet.json", std::ios::binary) << hash;
            std::ofstream(dir / "grape_sheet_array.json", std::ios::binary) << array;
            std::printf("wrote %s/grape_sheet.png, grape_sheet.json, grape_sheet_array.json\n", dir.string().c_str());
            return 0;
        }
        const grape::Image png = grape::Image::load_png(dir / "grape_sheet.png");
        const bool same_png = png.width() == drawn.image.width() && png.height() == drawn.image.height() &&
                              std::equal(png.argb().begin(), png.argb().end(), drawn.image.argb().begin());
        const bool same_hash = read_text(dir / "grape_sheet.json") == hash;
        const bool same_array = read_text(dir / "grape_sheet_array.json") == array;
        std::printf("png %s, hash json %s, array json %s\n", same_png ? "same" : "DIFFERS", same_hash ? "same" : "DIFFERS",
                    same_array ? "same" : "DIFFERS");
        return same_png && same_hash && same_array ? 0 : 1;
    } catch (const grape::Error& e) {
        std::fprintf(stderr, "make_sprite_sheet: %s\n", e.what());
        return 2;
    }
}
