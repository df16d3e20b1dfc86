// Sprites: the seed's SpritePlayer demo. One animation, drawn into a tile sheet with cairo at
// start-up, played two ways at the same real-valued rate: blitted from the sheet
// (TileSheetSprite) and stepped as a list of separate frame images (a Playable of our own,
// like the seed's MovieClip wrapper). A slider sets the rate from −(n−1) to n−1.
#include "studio.hpp"

#include "sheet.hpp"

#include <grape/sprite.hpp>

#include <SDL.h>

#include <cstdio>
#include <ostream>

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

class SpritesTab final : public Tab {
public:
    SpritesTab()
        : image_(draw_sprite_sheet(frame_count, columns, frame_size)),
          sheet_({.width = image_.width, .height = image_.height, .columns = columns,
                  .rows = (frame_count + columns - 1) / columns, .frame_count = frame_count}),
          sprite_(sheet_),
          sheet_player_(sprite_, {.rate = rate_}),
          list_player_(list_, {.rate = rate_}) {}

    const char* name() const noexcept override { return "sprites"; }
    const char* title() const noexcept override { return "Sprites"; }

    void attach(SDL_Renderer* renderer) override {
        sheet_texture_ = make_texture(renderer, image_.pixels.data(), image_.width, image_.height, image_.stride);
        // The list: each frame copied out of the sheet into its own texture.
        for (const FrameRect& r : sheet_.frames()) {
            const std::uint8_t* first = image_.pixels.data() + std::size_t(r.y) * std::size_t(image_.stride) + std::size_t(r.x) * 4;
            list_.frames.push_back(make_texture(renderer, first, r.width, r.height, image_.stride));
        }
    }

    void detach() override {
        for (SDL_Texture* t : list_.frames)
            if (t) SDL_DestroyTexture(t);
        list_.frames.clear();
        if (sheet_texture_) SDL_DestroyTexture(sheet_texture_);
        sheet_texture_ = nullptr;
    }

    void on_event(const SDL_Event& e) override {
        // Space runs and pauses, unless a text field has the keyboard.
        if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_SPACE && !e.key.repeat && !ImGui::GetIO().WantTextInput)
            running_ = !running_;
    }

    void advance(double dt) override {
        if (!running_) return;
        if (per_frame_) {
            // The seed's way: one advance per game frame, `rate` frames each.
            sheet_player_.advance();
            list_player_.advance();
        } else {
            sheet_player_.advance(dt, fps_);
            list_player_.advance(dt, fps_);
        }
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
        if (ImGui::Button(running_ ? "Pause" : "Run")) running_ = !running_;
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
    }

    void draw(ImDrawList* dl, ImVec2 min, ImVec2 max) override {
        const float big = std::min(220.0f, (max.x - min.x - 80.0f) / 2.0f);
        const ImVec2 a{min.x + 30.0f, min.y + 40.0f};
        dl->AddText({a.x, a.y - 20.0f}, colour::ink, "blitted from the tile sheet");
        if (sheet_texture_) {
            const FrameRect& r = sprite_.rect();
            const UvRect uv = sprite_.uv();
            (void)r;
            dl->AddImage(ImTextureID(sheet_texture_), a, {a.x + big, a.y + big}, {float(uv.u0), float(uv.v0)},
                         {float(uv.u1), float(uv.v1)});
        }
        const ImVec2 b{a.x + big + 40.0f, a.y};
        dl->AddText({b.x, b.y - 20.0f}, colour::ink, "list of frame images");
        if (list_.shown < list_.frames.size() && list_.frames[list_.shown])
            dl->AddImage(ImTextureID(list_.frames[list_.shown]), b, {b.x + big, b.y + big});
        char label[64];
        std::snprintf(label, sizeof label, "frame %zu / %d", sprite_.current_frame(), frame_count);
        dl->AddText({a.x, a.y + big + 6.0f}, colour::ink, label);
        std::snprintf(label, sizeof label, "frame %zu / %d", list_.shown, frame_count);
        dl->AddText({b.x, a.y + big + 6.0f}, colour::ink, label);

        // The whole sheet with the frame shown outlined.
        const float sy = a.y + big + 50.0f;
        const float sheet_w = std::min(float(image_.width), max.x - min.x - 60.0f);
        const float k = sheet_w / float(image_.width);
        dl->AddText({a.x, sy - 20.0f}, colour::ink, "the tile sheet (drawn with cairo at start-up)");
        if (sheet_texture_) dl->AddImage(ImTextureID(sheet_texture_), {a.x, sy}, {a.x + sheet_w, sy + float(image_.height) * k});
        const FrameRect& r = sprite_.rect();
        dl->AddRect({a.x + float(r.x) * k, sy + float(r.y) * k},
                    {a.x + float(r.x + r.width) * k, sy + float(r.y + r.height) * k}, colour::marker, 0.0f, 0, 3.0f);
    }

    void report(std::ostream& out) const override {
        out << "rate: " << sheet_player_.rate() << "\nsheet_frame: " << sprite_.current_frame()
            << "\nlist_frame: " << list_.shown << "\nrunning: " << running_ << "\n";
    }

private:
    void apply_rate() {
        sheet_player_.set_rate(rate_);
        list_player_.set_rate(rate_);
    }

    float rate_ = 1.0f;
    float fps_ = 12.0f;
    int mode_ = 0;
    bool per_frame_ = false;
    bool running_ = true;
    SheetImage image_;
    TileSheet sheet_;
    TileSheetSprite sprite_;
    FrameList list_;
    SpritePlayer sheet_player_;
    SpritePlayer list_player_;
    SDL_Texture* sheet_texture_ = nullptr;
};

}  // namespace

std::unique_ptr<Tab> make_sprites_tab() { return std::make_unique<SpritesTab>(); }

}  // namespace grape::studio
