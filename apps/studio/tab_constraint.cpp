#include "studio.hpp"
namespace grape::studio {
namespace {
class StubTab final : public Tab {
public:
    const char* name() const noexcept override { return "constraint"; }
    const char* title() const noexcept override { return "constraint"; }
    void advance(double) override {}
    void controls() override {}
    void draw(ImDrawList*, ImVec2, ImVec2) override {}
};
}  // namespace
std::unique_ptr<Tab> make_constraint_tab() { return std::make_unique<StubTab>(); }
}
