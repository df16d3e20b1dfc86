// Files written whole or not at all (src/internal/atomic_file.hpp): the bytes arrive intact,
// nothing is visible under the name before commit, and every failure leaves neither the
// file nor its temporary and names both the file and the reason. A full disk is tested on a
// real one by tests/tool_files.sh (a small tmpfs); here a file size limit of 0 (RLIMIT_FSIZE,
// SIGXFSZ ignored) makes every write fail with EFBIG, as a full disk fails with ENOSPC. (The
// temporaries are created exclusively, so a link planted at a temporary's name is never written
// through.)
#include "atomic_file.hpp"
#include "seeds.hpp"

#ifdef GRAPE_TEST_RENDER
#include <grape/render.hpp>
#include <grape/scene.hpp>
#endif

#include <grape/error.hpp>

#include <gtest/gtest.h>

#ifndef _WIN32
#include <sys/resource.h>
#endif
#include <unistd.h>

#include <csignal>

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

#ifndef _WIN32
// While it lives, every write of a file fails (EFBIG: a file size limit of 0) as on a full disk.
class FullDisk {
public:
    FullDisk() {
        ::getrlimit(RLIMIT_FSIZE, &old_);
        rlimit none = old_;
        none.rlim_cur = 0;
        ::setrlimit(RLIMIT_FSIZE, &none);
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);  // else the signal ends the process
    }
    ~FullDisk() {
        ::setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, old_handler_);
    }
    FullDisk(const FullDisk&) = delete;
    FullDisk& operator=(const FullDisk&) = delete;

private:
    rlimit old_{};
    void (*old_handler_)(int) = SIG_DFL;
};
constexpr bool can_fill_disk = true;
#else
// Windows has no per-process file size limit that makes writes fail, so the full-disk cases
// skip there (past the failing call the writer's error path is the POSIX one).
class FullDisk {
public:
    FullDisk() {}
};
constexpr bool can_fill_disk = false;
#endif

TEST_F(AtomicFileTest, AFullDiskIsReportedAndLeavesNothing) {
    if (!can_fill_disk) GTEST_SKIP() << "no file size limit (RLIMIT_FSIZE) on this system";
    const fs::path file = dir_ / "run.csv";
    {
        // Small writes stay in the buffer; the failure shows at commit at the latest.
        const FullDisk full;
        grape::detail::AtomicFile out(file);
        out.write("t,x\n");
        EXPECT_EQ(error_of([&] { out.commit(); }), "cannot write " + file.string() + ": file too large");
    }
    EXPECT_EQ(entries(), 0u);
    {
        // A large write fails at once.
        const FullDisk full;
        grape::detail::AtomicFile big(file);
        EXPECT_EQ(error_of([&] { big.write(std::string(1 << 20, 'x')); }), "cannot write " + file.string() + ": file too large");
    }
    EXPECT_EQ(entries(), 0u);
}

// Writers of one file at once (threads here, processes in tool.concurrent_*) each have a
// temporary of their own: each commit puts one whole file in place, the last one wins.
TEST_F(AtomicFileTest, WritersOfOneFileHaveTheirOwnTemporaries) {
    const fs::path file = dir_ / "out.png";
    grape::detail::AtomicFile a(file);
    grape::detail::AtomicFile b(file);
    EXPECT_NE(a.temporary(), b.temporary());
    a.write("first writer");
    b.write("second");
    b.commit();
    EXPECT_EQ(read(file), "second");
    a.commit();
    EXPECT_EQ(read(file), "first writer");
    EXPECT_EQ(entries(), 1u);
}

// A link planted where a fixed temporary name would be is neither followed nor truncated.
TEST_F(AtomicFileTest, ALinkAtATemporaryNameIsNotWrittenThrough) {
    const fs::path victim = dir_ / "victim.txt";
    grape::detail::write_file_atomically(victim, "keep");
    const fs::path file = dir_ / "out.png";
    fs::path planted = file;
    planted += ".partial";
    std::error_code made;
    fs::create_symlink(victim, planted, made);  // Windows makes links only with a privilege
    if (made) GTEST_SKIP() << "no symbolic link here: " << made.message();
    grape::detail::write_file_atomically(file, "new");
    EXPECT_EQ(read(victim), "keep");
    EXPECT_EQ(read(file), "new");
    EXPECT_TRUE(fs::is_symlink(planted));
}

#ifdef GRAPE_TEST_RENDER
TEST_F(AtomicFileTest, CanvasAndSceneReportAFullDisk) {
    if (!can_fill_disk) GTEST_SKIP() << "no file size limit (RLIMIT_FSIZE) on this system";
    grape::Canvas canvas(64, 48);
    canvas.stroke_line({0, 0}, {64, 48}, {});
    for (const char* name : {"p.png", "p.svg", "p.pdf"}) {
        const fs::path file = dir_ / name;
        {
            const FullDisk full;
            EXPECT_EQ(error_of([&] { canvas.write(file); }), "cannot write " + file.string() + ": file too large");
        }
        EXPECT_EQ(entries(), 0u) << name;
        canvas.write(file);  // and with room, the same call writes it
        EXPECT_GT(fs::file_size(file), 0u);
        fs::remove(file);
    }
    const fs::path scene_file = dir_ / "s.json";
    {
        const FullDisk full;
        EXPECT_EQ(error_of([&] { grape::save_scene_file(grape::Scene{}, scene_file); }),
                  "cannot write " + scene_file.string() + ": file too large");
    }
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
