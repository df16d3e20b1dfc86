// Sprites: the seed's SpritePlayer demo. One animation, the catalogue's grape sprite drawn into
// a tile sheet at start-up (scenes/sprite_sheets.hpp), played two ways at the same real-valued rate: blitted from the sheet
// (TileSheetSprite) and stepped as a list of separate frame images (a Playable of our own,
// like the seed's MovieClip wrapper). A slider sets the rate from −(n−1) to n−1. With the
// scene and render modules, a sheet exported from Aseprite or TexturePacker (JSON + PNG) opens
// too: its clips are listed and the chosen one plays with its own durations at the same rate.
#include "studio.hpp"

#include "sprite_sheets.hpp"

#include <grape/render.hpp>
#include <grape/sprite.hpp>

#if defined(GRAPE_STUDIO_SCENE) && defined(GRAPE_STUDIO_RENDER)
#define GRAPE_STUDIO_SHEETS 1
#include <grape/error.hpp>
#include <grape/render.hpp>
#include <grape/sprite_sheet_json.hpp>
#endif

#include <SDL.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace grape::studio {

namespace {

constexpr int frame_count = 12;
constexpr int columns = 6;
constexpr int frame_size = 96;

// A Playable over separate images, one texture per frame.
class FrameList final : public Playable {
public:
    std::vector<SDL_Texture*> frames;  // filled once the renderer exists
    std::size_t shown = 0;

    std::size_t frame_count() const noexcept override { return std::size_t(studio::frame_count); }
    void show_frame(std::size_t k) noexcept override { shown = k; }
};

SDL_Texture* make_texture(SDL_Renderer* renderer, const std::uint8_t* pixels, int w, int h, int stride) {
    SDL_Texture* t = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STATIC, w, h);
    if (!t) return nullptr;
    SDL_UpdateTexture(t, nullptr, pixels, stride);
    SDL_SetTextureBlendMode(t, SDL_BLENDMODE_BLEND);
    return t;
}

#ifdef GRAPE_STUDIO_SHEETS
// grape's own sheet, found at run time from where the program is: installed, it is in
// GRAPE_STUDIO_SHEET_DIR relative to the program's folder (share/grape/sprites beside bin);
// in a build tree the build copies it into sprites/ next to the program.
std::string default_sheet_file() {
    char* base = SDL_GetBasePath();
    if (!base) return "grape_sheet.json";
    const std::filesystem::path dir(base);
    SDL_free(base);
    const std::filesystem::path candidates[] = {dir / "sprites" / "grape_sheet.json",
                                                dir / GRAPE_STUDIO_SHEET_DIR / "grape_sheet.json"};
    for (const auto& file : candidates) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(file, ec)) return file.lexically_normal().string();
    }
    return candidates[1].lexically_normal().string();  // missing: the field shows it with the error
}
#endif

class SpritesTab final : public Tab {
public:
    explicit SpritesTab(std::string sheet_file)
        : sheet_file_option_(std::move(sheet_file)),
          image_(scenes::grape_tile_sheet(frame_count, columns, frame_size).image),
          sheet_({.width = image_.width(), .height = image_.height(), .columns = columns,
                  .rows = (frame_count + columns - 1) / columns, .frame_count = frame_count}),
          sprite_(sheet_),
          sheet_player_(sprite_, {.rate = rate_}),
          list_player_(list_, {.rate = rate_}) {}

    const char* name() const noexcept override { return "sprites"; }
    const char* title() const noexcept override { return "Sprites"; }

    void attach(SDL_Renderer* renderer) override {
        renderer_ = renderer;
#ifdef GRAPE_STUDIO_SHEETS
        const std::string file = sheet_file_option_.empty() ? default_sheet_file() : sheet_file_option_;
        std::snprintf(sheet_file_, sizeof sheet_file_, "%s", file.c_str());
        open_sheet();
#endif
        const auto* pixels = reinterpret_cast<const std::uint8_t*>(image_.argb().data());
        const int stride = 4 * image_.width();
        sheet_texture_ = make_texture(renderer, pixels, image_.width(), image_.height(), stride);
        // The list: each frame copied out of the sheet into its own texture.
        for (const FrameRect& r : sheet_.frames()) {
            const std::uint8_t* first = pixels + std::size_t(r.y) * std::size_t(stride) + std::size_t(r.x) * 4;
            list_.frames.push_back(make_texture(renderer, first, r.width, r.height, stride));
        }
    }

    void detach() override {
        for (SDL_Texture* t : list_.frames)
            if (t) SDL_DestroyTexture(t);
        list_.frames.clear();
        if (sheet_texture_) SDL_DestroyTexture(sheet_texture_);
        sheet_texture_ = nullptr;
#ifdef GRAPE_STUDIO_SHEETS
        if (clip_texture_) SDL_DestroyTexture(clip_texture_);  // the player stays for report()
        clip_texture_ = nullptr;
#endif
        renderer_ = nullptr;
    }

    void advance(double dt) override {
        if (per_frame_) {
            // The seed's way: one advance per game frame, `rate` frames each.
            sheet_player_.advance();
            list_player_.advance();
        } else {
            sheet_player_.advance(dt, fps_);
            list_player_.advance(dt, fps_);
        }
#ifdef GRAPE_STUDIO_SHEETS
        if (clip_player_) clip_player_->advance(dt);
#endif
    }

    void controls() override {
        ImGui::TextWrapped("SpritePlayer advances any Playable by a real-valued rate: 1 normal, 0.5 half "
                           "speed, -2 backwards at double speed. Left: blitted from the tile sheet; right: "
                           "the same animation as a list of frame images.");
        ImGui::Separator();
        const float cap = float(frame_count - 1);
        if (ImGui::SliderFloat("rate", &rate_, -cap, cap, "%.2f")) apply_rate();
        if (ImGui::Button("-1")) { rate_ = -1.0f; apply_rate(); }
        ImGui::SameLine();
        if (ImGui::Button("-0.5")) { rate_ = -0.5f; apply_rate(); }
        ImGui::SameLine();
        if (ImGui::Button("0")) { rate_ = 0.0f; apply_rate(); }
        ImGui::SameLine();
        if (ImGui::Button("0.5")) { rate_ = 0.5f; apply_rate(); }
        ImGui::SameLine();
        if (ImGui::Button("1")) { rate_ = 1.0f; apply_rate(); }
        ImGui::SameLine();
        if (ImGui::Button("2")) { rate_ = 2.0f; apply_rate(); }
        ImGui::Checkbox("one step per window frame (seed)", &per_frame_);
        if (!per_frame_) ImGui::SliderFloat("sheet fps", &fps_, 1.0f, 60.0f, "%.0f");
        static const char* modes[] = {"loop", "once", "ping-pong"};
        if (ImGui::Combo("at the ends", &mode_, modes, 3)) {
            const PlayMode m = mode_ == 0 ? PlayMode::loop : mode_ == 1 ? PlayMode::once : PlayMode::ping_pong;
            sheet_player_.set_mode(m);
            list_player_.set_mode(m);
        }
        run_button();
        ImGui::SameLine();
        if (ImGui::Button("Step")) {
            sheet_player_.advance();
            list_player_.advance();
        }
        ImGui::SameLine();
        if (ImGui::Button("Restart")) {
            sheet_player_.set_frame(0);
            list_player_.set_frame(0);
            sheet_player_.play();
            list_player_.play();
        }
        ImGui::Separator();
        ImGui::Text("rate after the cap: %.3f", sheet_player_.rate());
        ImGui::Text("sheet frame: %zu   list frame: %zu", sprite_.current_frame(), list_.shown);
        ImGui::Text("remainder: %+.3f", sheet_player_.remainder());
        ImGui::Text("playing: %s", sheet_player_.playing() ? "yes" : "no (finished or paused)");
#ifdef GRAPE_STUDIO_SHEETS
        sheet_controls();
#endif
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const float big = std::min(220.0f, (max.x - min.x - 80.0f) / 2.0f);
        const ImVec2 a{min.x + 30.0f, min.y + 40.0f};
        dl->AddText({a.x, a.y - 20.0f}, color::ink, "blitted from the tile sheet");
        if (sheet_texture_) {
            const FrameRect& r = sprite_.rect();
            const UvRect uv = sprite_.uv();
            (void)r;
            dl->AddImage(ImTextureID(sheet_texture_), a, {a.x + big, a.y + big}, {float(uv.u0), float(uv.v0)},
                         {float(uv.u1), float(uv.v1)});
        }
        const ImVec2 b{a.x + big + 40.0f, a.y};
        dl->AddText({b.x, b.y - 20.0f}, color::ink, "list of frame images");
        if (list_.shown < list_.frames.size() && list_.frames[list_.shown])
            dl->AddImage(ImTextureID(list_.frames[list_.shown]), b, {b.x + big, b.y + big});
        char label[64];
        std::snprintf(label, sizeof label, "frame %zu / %d", sprite_.current_frame(), frame_count);
        dl->AddText({a.x, a.y + big + 6.0f}, color::ink, label);
        std::snprintf(label, sizeof label, "frame %zu / %d", list_.shown, frame_count);
        dl->AddText({b.x, a.y + big + 6.0f}, color::ink, label);

        // The whole sheet with the frame shown outlined.
        const float sy = a.y + big + 50.0f;
        const float sheet_w = std::min(float(image_.width()), max.x - min.x - 60.0f);
        const float k = sheet_w / float(image_.width());
        dl->AddText({a.x, sy - 20.0f}, color::ink, "the tile sheet (drawn with cairo at start-up)");
        if (sheet_texture_) dl->AddImage(ImTextureID(sheet_texture_), {a.x, sy}, {a.x + sheet_w, sy + float(image_.height()) * k});
        const FrameRect& r = sprite_.rect();
        dl->AddRect({a.x + float(r.x) * k, sy + float(r.y) * k},
                    {a.x + float(r.x + r.width) * k, sy + float(r.y + r.height) * k}, color::marker, 0.0f, 0, 3.0f);
#ifdef GRAPE_STUDIO_SHEETS
        draw_clip(dl, {a.x + 2.0f * big + 80.0f, a.y});
#endif
    }

    void report(std::ostream& out) const override {
        out << "rate: " << sheet_player_.rate() << "\nsheet_frame: " << sprite_.current_frame()
            << "\nlist_frame: " << list_.shown << "\nrunning: " << running() << "\n";
#ifdef GRAPE_STUDIO_SHEETS
        if (clip_player_) {
            out << "clip: " << loaded_->clips()[clip_player_->clip()].name << "\nclip_frame: " << clip_player_->frame()
                << "\n";
        }
#endif
    }

private:
    void apply_rate() {
        sheet_player_.set_rate(rate_);
        list_player_.set_rate(rate_);
#ifdef GRAPE_STUDIO_SHEETS
        if (clip_player_) clip_player_->set_rate(rate_);
#endif
    }

#ifdef GRAPE_STUDIO_SHEETS
    // Reads the JSON named in the field and the PNG it names; on an error the message shows.
    void open_sheet() {
        close_sheet();
        try {
            loaded_.emplace(load_sprite_sheet_file(sheet_file_));
            const Image png = Image::load_png(sprite_sheet_image_path(*loaded_, sheet_file_));
            picture_size_ = {float(png.width()), float(png.height())};
            clip_texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STATIC, png.width(),
                                              png.height());
            if (clip_texture_) {
                SDL_UpdateTexture(clip_texture_, nullptr, png.argb().data(), png.width() * 4);
                SDL_SetTextureBlendMode(clip_texture_, SDL_BLENDMODE_BLEND);
            }
            if (loaded_->clips().empty()) {
                sheet_message_ = "no clips (tags) in this sheet";
            } else {
                clip_player_ = std::make_unique<ClipPlayer>(*loaded_, std::size_t{0}, ClipPlayerDef{.rate = rate_});
                sheet_message_.clear();
            }
        } catch (const Error& e) {
            close_sheet();
            sheet_message_ = e.what();
        }
    }

    void close_sheet() {
        clip_player_.reset();
        loaded_.reset();
        if (clip_texture_) SDL_DestroyTexture(clip_texture_);
        clip_texture_ = nullptr;
    }

    void sheet_controls() {
        ImGui::Separator();
        ImGui::TextWrapped("A sheet from Aseprite or TexturePacker (JSON + PNG): ClipPlayer plays a clip with its "
                           "frames' own durations at the rate above.");
        ImGui::InputText("sheet JSON", sheet_file_, sizeof sheet_file_);
        if (ImGui::Button("Open")) open_sheet();
        if (!sheet_message_.empty()) ImGui::TextWrapped("%s", sheet_message_.c_str());
        if (!clip_player_) return;
        const auto& clips = loaded_->clips();
        if (ImGui::BeginCombo("clip", clips[clip_player_->clip()].name.c_str())) {
            for (std::size_t k = 0; k < clips.size(); ++k) {
                if (ImGui::Selectable(clips[k].name.c_str(), k == clip_player_->clip())) clip_player_->play(k);
            }
            ImGui::EndCombo();
        }
        ImGui::Text("frame %zu (%.0f ms), pass %lld%s", clip_player_->frame(), loaded_->frame(clip_player_->frame()).duration_ms,
                    static_cast<long long>(clip_player_->pass()), clip_player_->finished() ? ", finished" : "");
        if (ImGui::Button("Play again")) clip_player_->play(clip_player_->clip());
    }

    // The frame shown, upright at three times its size in a box the size of its untrimmed
    // image, the pivot marked.
    void draw_clip(ImDrawList* dl, ImVec2 at) const {
        if (!clip_player_ || !clip_texture_) return;
        const SpriteFrame& f = loaded_->frame(clip_player_->frame());
        const float k = 3.0f;
        dl->AddText({at.x, at.y - 20.0f}, color::ink, clips_label().c_str());
        dl->AddRect(at, {at.x + float(f.source_width) * k, at.y + float(f.source_height) * k}, color::faint);
        const ImVec2 p{at.x + float(f.offset_x) * k, at.y + float(f.offset_y) * k};
        const ImVec2 q{p.x + float(f.width()) * k, p.y + float(f.height()) * k};
        const float u0 = float(f.rect.x) / picture_size_.x, v0 = float(f.rect.y) / picture_size_.y;
        const float u1 = float(f.rect.x + f.rect.width) / picture_size_.x;
        const float v1 = float(f.rect.y + f.rect.height) / picture_size_.y;
        if (f.rotated) {  // stored turned clockwise: the upright top-left is the region's top-right
            dl->AddImageQuad(ImTextureID(clip_texture_), p, {q.x, p.y}, q, {p.x, q.y}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0});
        } else {
            dl->AddImage(ImTextureID(clip_texture_), p, q, {u0, v0}, {u1, v1});
        }
        dl->AddCircleFilled({at.x + float(f.pivot.x) * k, at.y + float(f.pivot.y) * k}, 3.0f, color::marker);
    }

    std::string clips_label() const {
        return "clip '" + loaded_->clips()[clip_player_->clip()].name + "' from the sheet";
    }

    char sheet_file_[512] = {};
    std::optional<SpriteSheet> loaded_;
    std::unique_ptr<ClipPlayer> clip_player_;  // points into loaded_
    SDL_Texture* clip_texture_ = nullptr;
    ImVec2 picture_size_{1.0f, 1.0f};
    std::string sheet_message_;
#endif
    SDL_Renderer* renderer_ = nullptr;

    float rate_ = 1.0f;
    float fps_ = 12.0f;
    int mode_ = 0;
    bool per_frame_ = false;
    [[maybe_unused]] std::string sheet_file_option_;  // --sheet ("": grape's own sheet)
    Image image_;
    TileSheet sheet_;
    TileSheetSprite sprite_;
    FrameList list_;
    SpritePlayer sheet_player_;
    SpritePlayer list_player_;
    SDL_Texture* sheet_texture_ = nullptr;
};

}  // namespace

std::unique_ptr<Tab> make_sprites_tab(const std::string& sheet_file) { return std::make_unique<SpritesTab>(sheet_file); }

}  // namespace grape::studio
