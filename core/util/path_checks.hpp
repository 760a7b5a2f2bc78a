#pragma once
// Existence tests for paths users give that never throw. std::filesystem's
// plain overloads throw filesystem_error when the system cannot even look a
// path up (a name longer than the file system allows, a folder on the way
// that may not be searched); to the user such a path is as absent as a
// missing one, so the caller's own message ("expected an existing camera
// YAML file, got '...'") applies instead of a raw library error.
#include <filesystem>
#include <string>

namespace facadeslam {

bool path_exists(const std::filesystem::path& path);
bool is_existing_file(const std::filesystem::path& path);    // a regular file (or a link to one)
bool is_existing_folder(const std::filesystem::path& path);  // a directory (or a link to one)

// What is at `path`, for a message that says more than "does not exist":
// "does not exist", "is a folder", "is a FIFO (named pipe)", "is a character
// device", "is a block device", "is a socket", "is a file that cannot be read
// (Permission denied)", "is a file", or "cannot be looked up (<reason>)".
std::string describe_path(const std::filesystem::path& path);
// A regular file (or a link to one) that can be opened for reading.
bool is_readable_file(const std::filesystem::path& path);

}  // namespace facadeslam
