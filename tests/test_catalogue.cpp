// The catalogue: unique names, every entry builds and runs, and the scene files of the original's
// scenes hold the same paths as the catalogue's C++ entries (one source, checked).
#include "catalogue.hpp"

#include <grape/anim.hpp>
#include <grape/path.hpp>

#ifdef GRAPE_TEST_DYNAMICS
#include <grape/dynamics.hpp>
#endif
#ifdef GRAPE_TEST_SCENE
#include <grape/scene.hpp>
#endif

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

namespace {

using namespace grape;
using scenes::Category;

TEST(Catalogue, NamesAreUniqueAndFindable) {
    std::set<std::string> seen;
    for (const scenes::Entry& e : scenes::catalogue()) {
        EXPECT_TRUE(seen.insert(e.name).second) << "duplicate " << e.name;
        EXPECT_FALSE(e.summary.empty()) << e.name;
        for (const char c : e.name)
            EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
                        c == '_' || (e.category == Category::scene_file && c == '.'))
                << e.name;
        EXPECT_EQ(scenes::find_entry(e.name), &e);
        // Exactly the builder of its category.
        EXPECT_EQ(bool(e.path), e.category == Category::path) << e.name;
        EXPECT_EQ(bool(e.animation), e.category == Category::animation) << e.name;
        EXPECT_EQ(bool(e.system), e.category == Category::dynamics) << e.name;
        EXPECT_EQ(!e.file.empty(), e.category == Category::scene_file) << e.name;
        EXPECT_EQ(bool(e.sheet), e.category == Category::sprite_sheet) << e.name;
    }
    EXPECT_EQ(scenes::find_entry("no_such_scene"), nullptr);
    EXPECT_GE(scenes::entries_of(Category::path).size(), 25u);  // 9 of the original's, 15 kinds, 1 benchmark
    EXPECT_EQ(scenes::entries_of(Category::animation).size(), 2u);
    EXPECT_EQ(to_string(Category::scene_file), "scene_file");
    EXPECT_EQ(to_string(Category::sprite_sheet), "sprite_sheet");
#ifdef GRAPE_SCENES_SHEET_JSON
    EXPECT_EQ(scenes::entries_of(Category::sprite_sheet).size(), 2u);
#endif
}

TEST(Catalogue, EveryPathIsFiniteAndItsDescriptionRebuildsIt) {
    for (const scenes::Entry* e : scenes::entries_of(Category::path)) {
        const Path p = e->path();
        EXPECT_TRUE(std::isfinite(p.length()) && p.length() > 0.0) << e->name;
        const Path again = from_spec(describe(p));
        for (int k = 0; k <= 64; ++k) {
            const double u = k / 64.0;
            EXPECT_EQ(p.point(u).x, again.point(u).x) << e->name << " u " << u;
            EXPECT_EQ(p.point(u).y, again.point(u).y) << e->name << " u " << u;
        }
    }
}

TEST(Catalogue, EveryAnimationRunsToItsEnd) {
    for (const scenes::Entry* e : scenes::entries_of(Category::animation)) {
        Engine engine;
        scenes::Sprite view;
        const Animation a = e->animation(engine, view);
        ASSERT_TRUE(a.alive()) << e->name;
        const double end = a.duration() * (a.repetition() + 1);
        for (int k = 0; k < 600 && a.alive(); ++k) engine.tick(1.0 / 60.0);
        EXPECT_FALSE(a.alive()) << e->name << " still running after 10 s (one play of " << end << " s)";
        EXPECT_TRUE(std::isfinite(view.x) && std::isfinite(view.y)) << e->name;
    }
}

#ifdef GRAPE_TEST_DYNAMICS
TEST(Catalogue, EverySystemRunsTwoSecondsOnItsConstraints) {
    // As given, at 60 Hz, no sub-step count picked by hand: every state finite, and every
    // constraint held within 1e-6 m (a millionth of the 1 m links; the drift methods hold
    // far better, this bounds a failure, not the method).
    for (const scenes::Entry* e : scenes::entries_of(Category::dynamics)) {
        ParticleSystem system = e->system();
        ASSERT_GT(system.size(), 0u) << e->name;
        for (int frame = 0; frame < 120; ++frame) {
            const StepStats r = system.step(1.0 / 60.0);
            ASSERT_EQ(r.status, SolveStatus::ok) << e->name << " frame " << frame;
        }
        for (const Vec2 x : system.positions()) ASSERT_TRUE(std::isfinite(x.x) && std::isfinite(x.y)) << e->name;
        EXPECT_LT(system.max_residual().distance, 1e-6) << e->name;
    }
}
#endif

#ifdef GRAPE_TEST_SCENE
TEST(Catalogue, SceneFilesLoadAndHoldTheCataloguePaths) {
    // A scene file's path named N is the catalogue's seed_N: the same numbers, since the files
    // keep 17 significant digits and the original's coordinates are whole numbers.
    int shared = 0;
    for (const scenes::Entry* e : scenes::entries_of(Category::scene_file)) {
        const std::filesystem::path file = std::filesystem::path(GRAPE_SCENES_DIR) / e->file;
        ASSERT_TRUE(std::filesystem::exists(file)) << file;
        const Scene scene = load_scene_file(file);
        for (const NamedPath& p : scene.paths) {
            const scenes::Entry* c = scenes::find_entry("seed_" + p.name);
            if (!c || c->category != Category::path || e->name.rfind("seed_", 0) != 0) continue;
            ++shared;
            const Path expected = c->path();
            for (int k = 0; k <= 64; ++k) {
                const double u = k / 64.0;
                EXPECT_EQ(p.path.point(u).x, expected.point(u).x) << e->file << ": " << p.name << " u " << u;
                EXPECT_EQ(p.path.point(u).y, expected.point(u).y) << e->file << ": " << p.name << " u " << u;
            }
        }
    }
    EXPECT_GE(shared, 9);  // every path of the original's scene files
    // Every scene file in the folder is in the catalogue.
    for (const auto& f : std::filesystem::directory_iterator(GRAPE_SCENES_DIR)) {
        if (f.path().extension() == ".json") {
            EXPECT_NE(scenes::find_entry(f.path().filename().string()), nullptr) << f.path();
        }
    }
}
#endif

}  // namespace
