#include "studio.hpp"
namespace grape::studio {
namespace {
class PathsTab final : public Tab {
public:
    const char* name() const noexcept override { return "paths"; }
    const char* title() const noexcept override { return "Paths"; }
    void advance(double) override {}
    void controls() override { ImGui::TextUnformatted("paths"); }
    void draw(ImDrawList*, ImVec2, ImVec2) override {}
};
}  // namespace
std::unique_ptr<Tab> make_paths_tab() { return std::make_unique<PathsTab>(); }
}  // namespace grape::studio
