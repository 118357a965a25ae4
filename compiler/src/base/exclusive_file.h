// Files that this process can prove it created, and nothing else: the writers' temporaries and
// spool files. matc removes only such files (docs/reliability.md, "Nothing deleted that matc did
// not write").
#pragma once

#include <filesystem>
#include <string_view>

namespace matc {

// A new file that this process created: open()ed with O_EXCL as ".<stem>.matc-<64 random bits as
// hex>.tmp" in `directory`, so it never names a file that existed (an input, a user's file,
// another writer's temporary). Registered until it is renamed or discarded, so an interrupted run
// removes it (remove_temporaries_in_flight). Throws std::runtime_error when none can be created.
struct ExclusiveFile {
  std::filesystem::path path;
  int descriptor = -1;  // open for reading and writing; the caller closes it
};
ExclusiveFile create_exclusive_file(const std::filesystem::path& directory, std::string_view stem);
// Links the open file `descriptor` (an O_TMPFILE, which has no name) as `name`, through
// /proc/self/fd (linkat with AT_EMPTY_PATH needs CAP_DAC_READ_SEARCH): 0, or -1 with errno
// (EEXIST where something has that name).
int link_open_file(int descriptor, const std::filesystem::path& name);
// Gives the open file `descriptor` (an O_TMPFILE, which has no name) a new name as
// create_exclusive_file would make it, exclusively and registered the same way; returns it.
// Throws std::runtime_error when it cannot.
std::filesystem::path link_exclusive_file(int descriptor, const std::filesystem::path& directory,
                                          std::string_view stem);
// Removes a file create_exclusive_file made (and only such a file) and forgets it.
void discard_exclusive_file(const std::filesystem::path& path);
// Forgets it without removing it: it was renamed into place, or is unlinked by its user.
void forget_exclusive_file(const std::filesystem::path& path);

// Removes every temporary this process has created and not yet renamed into place or discarded,
// and refuses new ones: for a handler of SIGINT or SIGTERM, run on a thread of its own. matc
// removes no other file. Outputs are written unnamed where the system allows (pending_file.h), so
// a run killed outright (SIGKILL) leaves no ".*.matc-*.tmp" files there.
void remove_temporaries_in_flight();

}  // namespace matc
