#include "atomic_file.hpp"

#include <grape/error.hpp>

#include "utf8_path.hpp"

#ifdef _WIN32
#include "windows.hpp"
#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#else
#include <fcntl.h>
#include <sys/stat.h>
#include <pthread.h>
#include <unistd.h>
#endif

#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>
#include <utility>

namespace grape::detail {

// ------------------------------------------------------------- removal on SIGINT/SIGTERM

// The registry the signal handler walks: a list that only grows (entries are reused, never
// freed), published with release stores so the handler sees complete entries. The handler
// reads `path` only while `active`; entries are rewritten only while inactive, on the one
// thread that writes files (see remove_files_on_interrupt).
struct CleanupEntry {
    std::filesystem::path::string_type path;  // native: removed without converting in the handler
    std::atomic<bool> active{false};
    CleanupEntry* next = nullptr;       // registry order, fixed once published
    CleanupEntry* next_free = nullptr;  // free list, guarded by free_mutex
};

namespace {

// The system calls behind the interface: POSIX, or the Windows CRT and Win32 (whose file
// names are UTF-16 and whose rename does not replace an existing file).
#ifdef _WIN32
int remove_native(const wchar_t* file) noexcept { return ::_wunlink(file); }

// Creates FILE, failing with EEXIST if anything is there (so no other writer's temporary is
// truncated, and no link is followed).
int create_new(const std::filesystem::path& file) noexcept {
    return ::_wopen(file.c_str(), _O_WRONLY | _O_CREAT | _O_EXCL | _O_BINARY | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
}

unsigned long process_id() noexcept { return ::GetCurrentProcessId(); }

int write_some(int fd, const char* data, std::size_t size) noexcept {
    return ::_write(fd, data, static_cast<unsigned>(size < INT_MAX ? size : INT_MAX));
}

int close_file(int fd) noexcept { return ::_close(fd); }

// The errno closest to a Win32 error, so that messages read as on POSIX.
int errno_from_win32(DWORD error) noexcept {
    switch (error) {
        case ERROR_FILE_NOT_FOUND:
        case ERROR_PATH_NOT_FOUND:
        case ERROR_INVALID_DRIVE:
            return ENOENT;
        case ERROR_ACCESS_DENIED:
        case ERROR_SHARING_VIOLATION:
        case ERROR_LOCK_VIOLATION:
        case ERROR_WRITE_PROTECT:
            return EACCES;
        case ERROR_DISK_FULL:
        case ERROR_HANDLE_DISK_FULL:
            return ENOSPC;
        case ERROR_NOT_ENOUGH_MEMORY:
        case ERROR_OUTOFMEMORY:
            return ENOMEM;
        case ERROR_FILENAME_EXCED_RANGE:
            return ENAMETOOLONG;
        default:
            return EIO;
    }
}

// 0, or the errno of the failure.
int sync_file(int fd) noexcept {
    const auto handle = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
    if (handle == INVALID_HANDLE_VALUE) return EBADF;
    return ::FlushFileBuffers(handle) ? 0 : errno_from_win32(::GetLastError());
}

// 0, or the errno of the failure. WRITE_THROUGH: the rename is on the disk when it returns.
int replace_file(const std::filesystem::path& from, const std::filesystem::path& to) noexcept {
    if (::MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return 0;
    return errno_from_win32(::GetLastError());
}

void sync_folder(const std::filesystem::path&) noexcept {}  // MOVEFILE_WRITE_THROUGH did it
#else
int remove_native(const char* file) noexcept { return ::unlink(file); }

// Creates FILE, failing with EEXIST if anything is there (so no other writer's temporary is
// truncated, and no symbolic link is followed).
int create_new(const std::filesystem::path& file) noexcept {
    return ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
}

unsigned long process_id() noexcept { return static_cast<unsigned long>(::getpid()); }

ssize_t write_some(int fd, const char* data, std::size_t size) noexcept { return ::write(fd, data, size); }

int close_file(int fd) noexcept { return ::close(fd); }

// 0, or the errno of the failure; filesystems without fsync (EINVAL) are accepted.
int sync_file(int fd) noexcept { return ::fsync(fd) != 0 && errno != EINVAL ? errno : 0; }

// 0, or the errno of the failure.
int replace_file(const std::filesystem::path& from, const std::filesystem::path& to) noexcept {
    return ::rename(from.c_str(), to.c_str()) != 0 ? errno : 0;
}

// Makes a rename durable (best effort: not every filesystem syncs folders).
void sync_folder(const std::filesystem::path& folder) noexcept {
    const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}
#endif

std::atomic<CleanupEntry*> registry{nullptr};
std::atomic<bool> enabled{false};
std::mutex free_mutex;
CleanupEntry* free_list = nullptr;

static_assert(std::atomic<CleanupEntry*>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

CleanupEntry* register_path(const std::filesystem::path& path) {
    if (!enabled.load(std::memory_order_acquire)) return nullptr;
    std::lock_guard lock(free_mutex);
    CleanupEntry* e = free_list;
    if (e) {
        free_list = e->next_free;
        e->path = path.native();
    } else {
        e = new CleanupEntry;
        e->path = path.native();
        e->next = registry.load(std::memory_order_relaxed);
        registry.store(e, std::memory_order_release);
    }
    e->active.store(true, std::memory_order_release);
    return e;
}

void unregister(CleanupEntry* e) noexcept {
    if (!e) return;
    e->active.store(false, std::memory_order_release);
    std::lock_guard lock(free_mutex);
    e->next_free = free_list;
    free_list = e;
}

extern "C" void remove_registered_files(int signal_number) {
    // Only async-signal-safe calls: unlink, then the default action by re-raising (the
    // handler was installed with SA_RESETHAND, or by signal() on Windows, which resets it
    // too, so the pending signal ends the process).
    for (CleanupEntry* e = registry.load(std::memory_order_acquire); e; e = e->next)
        if (e->active.load(std::memory_order_acquire)) remove_native(e->path.c_str());
    ::raise(signal_number);
}

constexpr std::size_t buffer_size = 64 * 1024;

// Temporaries this process has named: with the process id, a name no other live writer uses,
// so concurrent writers of one FILE (processes or threads) never share a temporary.
std::atomic<unsigned long long> temporaries_named{0};

// A name can still be taken by a temporary a killed process left with a recycled id; a few
// more tries get past any such leftovers, and more than this means something else is wrong.
constexpr int temporary_attempts = 100;

}  // namespace

void remove_files_on_interrupt() {
    enabled.store(true, std::memory_order_release);
#ifdef _WIN32
    // Ctrl-C arrives as SIGINT (on a thread of its own); SIGTERM only from raise().
    std::signal(SIGINT, remove_registered_files);
    std::signal(SIGTERM, remove_registered_files);
#else
    struct sigaction action {};
    action.sa_handler = remove_registered_files;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
#endif
}

// ----------------------------------------------------------------------------- messages

std::string write_failure_reason(int err, const std::filesystem::path& file) {
    std::error_code ec;
    const auto parent = file.parent_path();
    if ((err == ENOENT || err == ENOTDIR) && !parent.empty() && !std::filesystem::is_directory(parent, ec))
        return "folder " + utf8_string(parent) + " does not exist";
    if (err == EISDIR || std::filesystem::is_directory(file, ec)) return "it is a folder";
    std::string reason = std::error_code(err, std::generic_category()).message();
    // "No space left on device" → "no space left on device"; keep "I/O error" as it is.
    if (reason.size() > 1 && std::isupper(static_cast<unsigned char>(reason[0])) &&
        std::islower(static_cast<unsigned char>(reason[1])))
        reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
    return reason;
}

// ----------------------------------------------------------------------------- AtomicFile

AtomicFile::AtomicFile(std::filesystem::path file) : file_(std::move(file)) {
    std::error_code ec;
    if (std::filesystem::is_directory(file_, ec)) throw Error("cannot write " + utf8_string(file_) + ": it is a folder");
    int err = EEXIST;
    for (int attempt = 0; attempt < temporary_attempts && err == EEXIST; ++attempt) {
        temporary_ = file_;
        temporary_ += ".partial-" + std::to_string(process_id()) + "-" +
                      std::to_string(temporaries_named.fetch_add(1, std::memory_order_relaxed));
        entry_ = register_path(temporary_);  // before the file exists, so no interruption misses it
        fd_ = create_new(temporary_);
        if (fd_ >= 0) break;
        err = errno;
        unregister(entry_);  // not ours: an interruption must not remove it
        entry_ = nullptr;
    }
    if (fd_ < 0) {
        throw Error("cannot write " + utf8_string(file_) + ": " +
                    (err == EEXIST ? std::string("every temporary name tried is taken")
                                   : write_failure_reason(err, file_)));
    }
    buffer_.reserve(buffer_size);
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
    if (fd_ >= 0) {
        close_file(fd_);
        fd_ = -1;
        remove_native(temporary_.c_str());
    }
    unregister(entry_);
    entry_ = nullptr;
}

bool AtomicFile::write_all(const char* p, std::size_t left) noexcept {
    while (left > 0) {
        const auto n = write_some(fd_, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            errno_ = errno;
            return false;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

bool AtomicFile::flush_buffer() noexcept {
    if (!write_all(buffer_.data(), buffer_.size())) return false;
    buffer_.clear();
    return true;
}

bool AtomicFile::append(std::string_view bytes) noexcept {
    if (fd_ < 0 || errno_ != 0) return false;
    if (buffer_.size() + bytes.size() > buffer_size && !flush_buffer()) return false;
    if (bytes.size() >= buffer_size) return write_all(bytes.data(), bytes.size());  // large blocks go straight through
    buffer_.append(bytes);  // fits in the reserved capacity: no allocation
    return true;
}

void AtomicFile::write(std::string_view bytes) {
    if (!append(bytes)) fail();
}

void AtomicFile::fail(std::string_view reason) {
    const int err = errno_ ? errno_ : EIO;
    discard();
    throw Error("cannot write " + utf8_string(file_) + ": " +
                (reason.empty() ? write_failure_reason(err, file_) : std::string(reason)));
}

void AtomicFile::commit() {
    if (fd_ < 0) throw Error("cannot write " + utf8_string(file_) + ": already committed or discarded");
    if (errno_ != 0 || !flush_buffer()) fail();
    // The data reaches the disk before the rename makes it visible: after a crash the file
    // is the old one or the whole new one.
    if (const int err = sync_file(fd_)) {
        errno_ = err;
        fail();
    }
    const int fd = std::exchange(fd_, -1);
    if (close_file(fd) != 0 && errno != EINTR) {  // NFS reports deferred write errors here
        errno_ = errno;
        remove_native(temporary_.c_str());
        fail();
    }
    if (const int err = replace_file(temporary_, file_)) {
        errno_ = err;
        remove_native(temporary_.c_str());
        fail();
    }
    unregister(entry_);
    entry_ = nullptr;
    sync_folder(file_.parent_path());
}

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes) {
    AtomicFile out(file);
    out.write(bytes);
    out.commit();
}

// -------------------------------------------------------------------------- StagingFolder

StagingFolder::StagingFolder(std::filesystem::path folder, std::filesystem::path created)
    : folder_(std::move(folder)), created_(std::move(created)) {
    std::error_code ec;
    for (int attempt = 0; attempt < temporary_attempts; ++attempt) {
        staging_ = folder_ / (".partial-" + std::to_string(process_id()) + "-" +
                              std::to_string(temporaries_named.fetch_add(1, std::memory_order_relaxed)));
        if (std::filesystem::create_directory(staging_, ec)) return;
        if (ec) break;  // false without an error: the name is taken, try the next
    }
    const int err = ec ? ec.default_error_condition().value() : EEXIST;
    staging_.clear();
    throw Error("cannot write " + utf8_string(folder_) + ": " +
                (err == EEXIST ? std::string("every temporary name tried is taken") : write_failure_reason(err, folder_)));
}

StagingFolder::~StagingFolder() {
    if (committed_ || staging_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(staging_, ec);
    if (created_.empty()) return;
    // Only empty folders go (remove fails on any other): what was put there meanwhile stays.
    for (std::filesystem::path p = folder_; !p.empty(); p = p.parent_path()) {
        if (!std::filesystem::remove(p, ec) || p == created_ || p == p.parent_path()) break;
    }
}

void StagingFolder::commit() {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(staging_, ec)) {
        const std::filesystem::path to = folder_ / entry.path().filename();
        if (const int err = replace_file(entry.path(), to))
            throw Error("cannot write " + utf8_string(to) + ": " + write_failure_reason(err, to));
    }
    if (ec) throw Error("cannot write " + utf8_string(folder_) + ": " + write_failure_reason(ec.default_error_condition().value(), folder_));
    std::filesystem::remove(staging_, ec);
    committed_ = true;
    sync_folder(folder_);
}

// ------------------------------------------------------------------------------- RunFiles

#ifdef _WIN32
InterruptsDeferred::InterruptsDeferred() noexcept : saved_{} {}
InterruptsDeferred::~InterruptsDeferred() = default;
#else
InterruptsDeferred::InterruptsDeferred() noexcept : saved_{} {
    static_assert(sizeof(sigset_t) <= sizeof(saved_), "sigset_t does not fit");
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    std::memcpy(saved_, &old, sizeof old);
}
InterruptsDeferred::~InterruptsDeferred() {
    sigset_t old;
    std::memcpy(&old, saved_, sizeof old);
    pthread_sigmask(SIG_SETMASK, &old, nullptr);  // a signal that waited is delivered now
}
#endif

RunFiles::~RunFiles() {
    for (CleanupEntry* e : entries_) unregister(e);
    if (kept_) return;
    std::error_code ec;
    for (const auto& f : files_) std::filesystem::remove(f, ec);
}

void RunFiles::add(const std::filesystem::path& file) {
    files_.push_back(file);
    entries_.reserve(files_.size());
    if (CleanupEntry* e = register_path(file)) entries_.push_back(e);
}

void RunFiles::keep() noexcept {
    kept_ = true;
    for (CleanupEntry* e : entries_) unregister(e);
    entries_.clear();
}

}  // namespace grape::detail
