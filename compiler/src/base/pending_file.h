// An output being written before it has its name (docs/reliability.md, "Nothing partial"). On
// Linux it is an O_TMPFILE in the output's directory: a file with no name at all until it is
// complete, so a run killed outright (SIGKILL) leaves nothing behind. Where the file system or
// the kernel has no O_TMPFILE, or the process cannot link one (no /proc, no capability), it is a
// named exclusive temporary (create_exclusive_file), as matc wrote before.
#pragma once

#include <filesystem>
#include <string_view>

namespace matc {

class PendingFile {
 public:
  // A new, empty file in `directory` for an output called `name` there (the temporary's stem
  // where it needs one). Throws std::runtime_error when none can be created.
  static PendingFile create(const std::filesystem::path& directory, std::string_view name);

  PendingFile(PendingFile&& other) noexcept;
  PendingFile& operator=(PendingFile&& other) noexcept;
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  ~PendingFile();  // discards a file never published

  // Open for reading and writing until published or discarded.
  int descriptor() const { return descriptor_; }
  // Whether it has a name yet (only the fallback's temporaries do).
  bool named() const { return !temporary_.empty(); }

  // Gives the complete file the name `target`, replacing what is there as rename(2) does, and
  // closes it. An unnamed file takes an absent target's name directly (linkat); an existing target
  // is replaced through an exclusive temporary name renamed over it, the one moment (two system
  // calls) such a file has a name. Throws std::runtime_error naming `target` on failure, leaving
  // no temporary and `target` as it was.
  void publish(const std::filesystem::path& target);
  // Closes and forgets it (removing the fallback's temporary).
  void discard() noexcept;

 private:
  PendingFile(int descriptor, std::filesystem::path directory, std::filesystem::path temporary)
      : descriptor_(descriptor),
        directory_(std::move(directory)),
        temporary_(std::move(temporary)) {}

  int descriptor_ = -1;
  std::filesystem::path directory_;
  std::filesystem::path temporary_;  // the fallback's named temporary; empty when unnamed
};

}  // namespace matc
