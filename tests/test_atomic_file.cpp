// Files written whole or not at all (src/internal/atomic_file.hpp): the bytes arrive intact,
// nothing is visible under the name before commit, and every failure leaves neither the
// file nor its temporary and names both the file and the reason. A full disk is tested on a
// real one by tests/full_disk.sh (a small tmpfs); here the temporary is a link to /dev/full,
// whose every write fails with ENOSPC.
#include "atomic_file.hpp"
#include "seeds.hpp"

#ifdef GRAPE_TEST_RENDER
#include <grape/render.hpp>
#include <grape/scene.hpp>
#endif

#include <grape/error.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

// A fresh folder per test, removed afterwards.
class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("grape-atomic-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    static std::string read(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }
    // The message of the grape::Error that f throws ("" if none).
    template <class F>
    static std::string error_of(F f) {
        try {
            f();
        } catch (const grape::Error& e) {
            return e.what();
        }
        return "";
    }
    fs::path dir_;
};

TEST_F(AtomicFileTest, BytesArriveWholeAndOnlyAtCommit) {
    // Random sizes around the 64 KiB buffer: small writes, writes that fill it exactly and
    // blocks larger than it, compared byte for byte with what was written.
    std::mt19937 rng(static_cast<std::uint32_t>(grape::testing::test_seed(19)));
    std::string expected;
    const fs::path file = dir_ / "data.bin";
    {
        grape::detail::AtomicFile out(file);
        for (int i = 0; i < 200; ++i) {
            const std::size_t n = std::uniform_int_distribution<std::size_t>(0, i % 10 == 0 ? 200000 : 3000)(rng);
            std::string block(n, '\0');
            for (char& c : block) c = static_cast<char>(rng());
            out.write(block);
            expected += block;
        }
        EXPECT_FALSE(fs::exists(file));  // nothing under the name before commit
        EXPECT_TRUE(fs::exists(out.temporary()));
        out.commit();
        EXPECT_FALSE(fs::exists(out.temporary()));
    }
    EXPECT_EQ(read(file), expected);
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, ReplacesAnOldFileOnlyWhenComplete) {
    const fs::path file = dir_ / "scene.json";
    grape::detail::write_file_atomically(file, "old");
    {
        grape::detail::AtomicFile out(file);
        out.write("new, unfinished");
        EXPECT_EQ(read(file), "old");
    }  // abandoned: the old file stays, the temporary goes
    EXPECT_EQ(read(file), "old");
    EXPECT_EQ(entries(), 1u);
    grape::detail::write_file_atomically(file, "new");
    EXPECT_EQ(read(file), "new");
}

TEST_F(AtomicFileTest, AFolderInTheWayIsNamedAndNothingIsLeft) {
    const fs::path folder = dir_ / "out.png";
    fs::create_directory(folder);
    EXPECT_EQ(error_of([&] { grape::detail::write_file_atomically(folder, "x"); }),
              "cannot write " + folder.string() + ": it is a folder");
    EXPECT_TRUE(fs::is_directory(folder));
    EXPECT_EQ(entries(), 1u);
    // The folder appearing while the file is written: the rename fails, with the reason.
    const fs::path late = dir_ / "late.png";
    grape::detail::AtomicFile out(late);
    out.write("x");
    fs::create_directory(late);
    fs::create_directory(late / "inside");  // a non-empty folder: rename cannot replace it
    EXPECT_EQ(error_of([&] { out.commit(); }), "cannot write " + late.string() + ": it is a folder");
    EXPECT_FALSE(fs::exists(out.temporary()));
}

// The next write to FILE's temporary fails as on a full disk.
void fill_disk_for(const fs::path& file) {
    fs::path tmp = file;
    tmp += ".partial";
    fs::create_symlink("/dev/full", tmp);
}

TEST_F(AtomicFileTest, AFullDiskIsReportedAndLeavesNothing) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    const fs::path file = dir_ / "run.csv";
    fill_disk_for(file);
    // Small writes stay in the buffer; the failure shows at commit at the latest.
    grape::detail::AtomicFile out(file);
    out.write("t,x\n");
    EXPECT_EQ(error_of([&] { out.commit(); }), "cannot write " + file.string() + ": no space left on device");
    EXPECT_EQ(entries(), 0u);
    // A large write fails at once.
    fill_disk_for(file);
    grape::detail::AtomicFile big(file);
    EXPECT_EQ(error_of([&] { big.write(std::string(1 << 20, 'x')); }), "cannot write " + file.string() + ": no space left on device");
    EXPECT_EQ(entries(), 0u);
}

#ifdef GRAPE_TEST_RENDER
TEST_F(AtomicFileTest, CanvasAndSceneReportAFullDisk) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    grape::Canvas canvas(64, 48);
    canvas.stroke_line({0, 0}, {64, 48}, {});
    for (const char* name : {"p.png", "p.svg", "p.pdf"}) {
        const fs::path file = dir_ / name;
        fill_disk_for(file);
        EXPECT_EQ(error_of([&] { canvas.write(file); }), "cannot write " + file.string() + ": no space left on device");
        EXPECT_EQ(entries(), 0u) << name;
        canvas.write(file);  // and with room, the same call writes it
        EXPECT_GT(fs::file_size(file), 0u);
        fs::remove(file);
    }
    const fs::path scene_file = dir_ / "s.json";
    fill_disk_for(scene_file);
    EXPECT_EQ(error_of([&] { grape::save_scene_file(grape::Scene{}, scene_file); }),
              "cannot write " + scene_file.string() + ": no space left on device");
    EXPECT_EQ(entries(), 0u);
}
#endif

TEST_F(AtomicFileTest, AMissingFolderIsNamed) {
    const fs::path file = dir_ / "none" / "x.svg";
    EXPECT_EQ(error_of([&] { grape::detail::write_file_atomically(file, "x"); }),
              "cannot write " + file.string() + ": folder " + (dir_ / "none").string() + " does not exist");
}

TEST_F(AtomicFileTest, ReasonsReadAsErrnoSaysInLowerCase) {
    EXPECT_EQ(grape::detail::write_failure_reason(ENOSPC, dir_ / "a.png"), "no space left on device");
    EXPECT_EQ(grape::detail::write_failure_reason(EACCES, dir_ / "a.png"), "permission denied");
    EXPECT_EQ(grape::detail::write_failure_reason(EIO, dir_ / "a.png"), "input/output error");
}

TEST_F(AtomicFileTest, RunFilesAreRemovedUnlessKept) {
    {
        grape::detail::RunFiles run;
        for (int i = 0; i < 3; ++i) {
            const fs::path f = dir_ / ("frame-" + std::to_string(i) + ".png");
            run.add(f);
            grape::detail::write_file_atomically(f, "frame");
        }
        run.add(dir_ / "never-written.png");  // registered, then the run failed
        EXPECT_EQ(entries(), 3u);
    }
    EXPECT_EQ(entries(), 0u);
    {
        grape::detail::RunFiles run;
        run.add(dir_ / "kept.png");
        grape::detail::write_file_atomically(dir_ / "kept.png", "frame");
        run.keep();
    }
    EXPECT_EQ(entries(), 1u);
}

}  // namespace
