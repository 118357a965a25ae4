#include "pipeline/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <future>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "base/pending_file.h"

namespace matc {
namespace {

// What is at an output's path, from one lstat (a batch makes thousands of these): nothing, a
// regular file and its size, a directory, or something else (a symlink is replaced, never read
// or written through).
struct Target {
  enum class Kind { absent, regular, directory, other } kind = Kind::absent;
  std::uintmax_t size = 0;
};

Target inspect(const std::filesystem::path& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) return {};
  if (S_ISREG(status.st_mode))
    return {Target::Kind::regular, static_cast<std::uintmax_t>(status.st_size)};
  return {S_ISDIR(status.st_mode) ? Target::Kind::directory : Target::Kind::other, 0};
}

bool holds_bytes(const Target& target, const std::filesystem::path& path, std::string_view bytes) {
  if (target.kind != Target::Kind::regular || target.size != bytes.size()) return false;
  std::ifstream in(path, std::ios::binary);
  const std::string existing((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  return existing == bytes;
}

// Whether the pending file `pending` (written, its offset anywhere) and the output `b` hold the
// same bytes, read a block at a time (a symlink at `b` is never read: it is replaced).
bool same_contents(int pending, const std::filesystem::path& b) {
  const Target existing = inspect(b);
  struct stat status {};
  if (::fstat(pending, &status) != 0 || existing.kind != Target::Kind::regular ||
      existing.size != static_cast<std::uintmax_t>(status.st_size))
    return false;
  std::ifstream in_b(b, std::ios::binary);
  std::string block_a(1 << 16, '\0');
  std::string block_b(1 << 16, '\0');
  off_t offset = 0;
  while (in_b) {
    const ssize_t read_a = ::pread(pending, block_a.data(), block_a.size(), offset);
    in_b.read(block_b.data(), static_cast<std::streamsize>(block_b.size()));
    if (read_a < 0 || read_a != in_b.gcount() ||
        block_a.compare(0, static_cast<std::size_t>(read_a), block_b, 0,
                        static_cast<std::size_t>(read_a)) != 0)
      return false;
    offset += read_a;
  }
  return offset == status.st_size;
}

// Writes `size` bytes to `descriptor`, through partial writes and interruptions.
bool write_fully(int descriptor, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(descriptor, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

// Writes what a stream is given to a file descriptor (the temporary's, opened exclusively), so
// nothing between creating the name and writing it can redirect the bytes elsewhere. Small pieces
// are gathered in a buffer; a piece as large as the buffer goes straight to the descriptor (baked
// textures run to hundreds of MB).
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int descriptor) : descriptor_(descriptor), buffer_(1 << 16) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  ~DescriptorBuffer() override { sync(); }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* data, std::streamsize count) override {
    if (count < static_cast<std::streamsize>(buffer_.size()))
      return std::streambuf::xsputn(data, count);
    if (sync() != 0 || !write_fully(descriptor_, data, static_cast<std::size_t>(count))) return 0;
    return count;
  }
  int sync() override {
    if (!write_fully(descriptor_, pbase(), static_cast<std::size_t>(pptr() - pbase()))) return -1;
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return 0;
  }

 private:
  int descriptor_;
  std::vector<char> buffer_;
};

// A pending file for `path` (pending_file.h: unnamed until published), written with `produce`;
// nothing of it is left on failure.
PendingFile write_pending(const std::filesystem::path& path,
                          const std::function<void(std::ostream&)>& produce) {
  PendingFile file = PendingFile::create(path.parent_path(), path.filename().string());
  bool written = false;
  std::string failure;
  {
    DescriptorBuffer buffer(file.descriptor());
    std::ostream out(&buffer);
    produce(out);  // an exception discards the file (its destructor)
    out.flush();
    written = static_cast<bool>(out);
    if (!written) failure = std::strerror(errno);
  }
  if (!written)
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path.string(), failure));
  return file;
}

// write_pending for bytes already in memory.
PendingFile write_pending(const std::filesystem::path& path, std::string_view bytes) {
  return write_pending(path, [bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace

WriteOutcome write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  if (holds_bytes(inspect(path), path, bytes)) return WriteOutcome::unchanged;
  write_pending(path, bytes).publish(path);
  return WriteOutcome::written;
}

WriteOutcome write_file_atomically(const std::filesystem::path& path,
                                   const std::function<void(std::ostream&)>& produce) {
  PendingFile pending = write_pending(path, produce);
  if (same_contents(pending.descriptor(), path)) return WriteOutcome::unchanged;  // discarded
  pending.publish(path);
  return WriteOutcome::written;
}

std::vector<WriteOutcome> write_files_atomically(const std::filesystem::path& directory,
                                                 std::span<const OutputFile> files) {
  std::vector<WriteOutcome> outcomes(files.size(), WriteOutcome::unchanged);
  std::vector<std::optional<PendingFile>> pending(files.size());  // discarded when destroyed
  // Large sets (baked textures, hundreds of MB) are written on a thread per file: copying into
  // the page cache is most of a write's time. Small ones (a material's shaders) on this thread.
  std::size_t total_bytes = 0;
  for (const OutputFile& file : files)
    total_bytes += file.bytes.size();
  const bool in_parallel = files.size() > 1 && total_bytes >= (std::size_t{8} << 20);
  const auto prepare = [&](std::size_t i) {
    const std::filesystem::path target = directory / files[i].name;
    const Target existing = inspect(target);
    if (holds_bytes(existing, target, files[i].bytes)) return;
    if (existing.kind == Target::Kind::directory)
      throw std::runtime_error(
          fmt::format("cannot replace '{}': it is a directory", target.string()));
    pending[i] = write_pending(target, files[i].bytes);
    outcomes[i] = WriteOutcome::written;
  };
  std::exception_ptr failure;
  if (in_parallel) {
    std::vector<std::future<void>> writes;
    for (std::size_t i = 0; i < files.size(); ++i)
      writes.push_back(std::async(std::launch::async, prepare, i));
    for (std::future<void>& write : writes) {  // every one waited for before rethrowing
      try {
        write.get();
      } catch (...) {
        if (!failure) failure = std::current_exception();
      }
    }
  } else {
    try {
      for (std::size_t i = 0; i < files.size(); ++i)
        prepare(i);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  // A failure here leaves the targets already published with their new bytes.
  for (std::size_t i = 0; i < files.size(); ++i)
    if (pending[i]) pending[i]->publish(directory / files[i].name);
  return outcomes;
}

bool same_file_contents(const std::filesystem::path& a, const std::filesystem::path& b) {
  const int descriptor = ::open(a.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) return false;
  const bool same = same_contents(descriptor, b);
  ::close(descriptor);
  return same;
}

std::string path_identity(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? path.lexically_normal().string() : canonical.string();
}

}  // namespace matc
