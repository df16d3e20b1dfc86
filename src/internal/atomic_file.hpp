// Files written in full or not at all, for the render and scene modules and the grape tool
// (internal: not installed). Bytes go to a sibling temporary FILE.partial-PID-N that only this
// writer uses (created exclusively: O_EXCL, or _O_EXCL on Windows); commit() flushes them,
// fsyncs, and renames the temporary over FILE (on Windows: FlushFileBuffers, then MoveFileExW
// replacing FILE), so a reader sees the old file or one writer's whole new one, and of many
// concurrent writers of FILE the last rename wins. Every failure (a full disk, a missing
// folder, a folder in the way) throws grape::Error "cannot write FILE: REASON" and leaves
// neither FILE nor the temporary behind.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grape::detail {

struct CleanupEntry;

/// One file being written; destroying it uncommitted removes the temporary.
class AtomicFile {
public:
    /// Creates this writer's temporary beside FILE; throws if FILE is a folder or it cannot be created.
    explicit AtomicFile(std::filesystem::path file);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Appends bytes; throws on a failed write (the reason from errno, e.g. "no space left on device").
    void write(std::string_view bytes);
    /// Appends bytes without throwing (for C callbacks such as cairo's); false once any write failed.
    bool append(std::string_view bytes) noexcept;
    /// Flushes, fsyncs and renames the temporary over the file; throws (removing the temporary) on failure.
    void commit();
    /// Removes the temporary and throws "cannot write FILE: REASON" (the recorded errno's reason if
    /// REASON is empty and a write failed).
    [[noreturn]] void fail(std::string_view reason = {});

    const std::filesystem::path& file() const noexcept { return file_; }
    const std::filesystem::path& temporary() const noexcept { return temporary_; }

private:
    bool write_all(const char* data, std::size_t size) noexcept;
    bool flush_buffer() noexcept;
    void discard() noexcept;

    std::filesystem::path file_;
    std::filesystem::path temporary_;
    int fd_ = -1;
    int errno_ = 0;  // first failed write's errno
    std::string buffer_;
    CleanupEntry* entry_ = nullptr;  // the temporary, removed if the process is interrupted
};

/// Writes the whole of BYTES to FILE through an AtomicFile.
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

/// The reason a write to FILE failed with errno ERR, as messages quote it: lower case
/// ("no space left on device"), or "folder F does not exist" for a missing folder.
std::string write_failure_reason(int err, const std::filesystem::path& file);

/// A folder's new files made visible together: they are written into a fresh staging folder
/// inside FOLDER (.partial-PID-N), and commit() moves each over its name in FOLDER. Destroyed
/// without commit() (the run failed), it removes the staging folder with everything in it,
/// and then FOLDER and its parents up to CREATED (the outermost folder the run created; empty:
/// none), each only if empty. So a failed run leaves FOLDER as it was, or gone if it made it.
class StagingFolder {
public:
    /// Creates the staging folder; throws "cannot write FOLDER: REASON".
    explicit StagingFolder(std::filesystem::path folder, std::filesystem::path created = {});
    ~StagingFolder();
    StagingFolder(const StagingFolder&) = delete;
    StagingFolder& operator=(const StagingFolder&) = delete;

    /// Where to write the files.
    const std::filesystem::path& path() const noexcept { return staging_; }
    /// Moves every staged file over its name in FOLDER and removes the staging folder; throws
    /// "cannot write FILE: REASON" if a move fails (the files not yet moved are removed).
    void commit();

private:
    std::filesystem::path folder_;
    std::filesystem::path staging_;
    std::filesystem::path created_;
    bool committed_ = false;
};

/// Makes SIGINT and SIGTERM remove every file registered here (temporaries of AtomicFiles,
/// the files of an unfinished RunFiles), then end the process by the same signal. For
/// single-threaded programs such as the grape tool; call once at start.
void remove_files_on_interrupt();

/// While one lives, SIGINT and SIGTERM wait (POSIX: blocked on this thread, delivered when it
/// ends): for a step that must not be cut in two, such as a file committed and then added to
/// a RunFiles (cut between the two, the committed file would be neither a temporary nor a
/// run's file, and would stay). On Windows, where Ctrl-C runs its handler on a thread of its
/// own, it does nothing.
class InterruptsDeferred {
public:
    InterruptsDeferred() noexcept;
    ~InterruptsDeferred();
    InterruptsDeferred(const InterruptsDeferred&) = delete;
    InterruptsDeferred& operator=(const InterruptsDeferred&) = delete;

private:
    unsigned char saved_[256];  // the previous signal mask (a sigset_t fits: 128 bytes on glibc)
};

/// The files one multi-file run creates (the frames of `grape render --frames`): all of them
/// are removed if the run fails (destroyed without keep()) or is interrupted.
class RunFiles {
public:
    RunFiles() = default;
    ~RunFiles();
    RunFiles(const RunFiles&) = delete;
    RunFiles& operator=(const RunFiles&) = delete;

    /// Registers FILE before it is written, so an interruption while it is written removes it too.
    void add(const std::filesystem::path& file);
    /// The run is complete: its files stay.
    void keep() noexcept;
    std::size_t size() const noexcept { return files_.size(); }

private:
    std::vector<std::filesystem::path> files_;
    std::vector<CleanupEntry*> entries_;  // the same files, for the interrupt handler
    bool kept_ = false;
};

}  // namespace grape::detail
