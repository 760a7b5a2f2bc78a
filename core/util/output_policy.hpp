#pragma once
// The one rule every command's outputs follow, checked before any work so
// that a careless command line never destroys a user's files:
//  - an output file replaces only a file of its own kind that this program
//    wrote, recognised by its content (a report's keys, a map's magic, the
//    text chunk in its PNGs...), never a user's file that happens to have the name;
//  - an output folder, replaced as a whole (staged_folder.hpp), replaces only
//    an earlier output folder each entry of which is one the command writes
//    there (name and content), nothing else;
//  - no output is an input, or holds one (paths resolved, symlinks
//    followed), and no output file lies in a folder whose every file is read
//    (an image folder: the output would be read as an image next time);
//  - no two outputs of one run are the same path, and an output inside
//    another output folder takes a name that folder's command leaves free.
// The command-specific kinds and folder layouts live with the commands
// (apps/output_kinds.hpp); this file knows none of them.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace facadeslam {

// A kind of file this program writes and how to recognise one on disk.
struct OutputFileKind {
  std::string description;  // "a replay report (report.json)": said when a file is not one
  // Reads the (regular) file; true when it is one of this kind.
  std::function<bool(const std::filesystem::path&)> recognises;
};

// Files that start with `prefix` (a magic number).
OutputFileKind file_starting_with(std::string description, std::string prefix);
// PNG pictures this program wrote (png_signature.hpp): a user's photo of
// the same name is not one.
OutputFileKind png_file(std::string description);
// A JSON object holding every one of `keys` (none: any JSON object).
OutputFileKind json_object_with_keys(std::string description, std::vector<std::string> keys);
// Text, one line of which (within the first 64 KiB) starts with `line_prefix`.
OutputFileKind text_with_line(std::string description, std::string line_prefix);
// Text whose records (blank lines and '#' comments aside) each start with a
// number: TUM trajectories and image lists, class tables.
OutputFileKind numbered_lines(std::string description);
// Text (no NUL byte in its first 64 KiB): a copy of the user's own scene.
OutputFileKind text_file(std::string description);
// A file of any of `kinds`.
OutputFileKind any_of(std::string description, std::vector<OutputFileKind> kinds);

struct OutputFolderLayout;

// An entry an output folder may hold: a file of a kind or a folder laid out
// so, under a name or a pattern with one '*' ("generation-*.json").
struct OutputFolderEntry {
  std::string pattern;
  OutputFileKind file;                               // when `folder` is empty
  std::shared_ptr<const OutputFolderLayout> folder;  // else a folder laid out so
  // Written by every run of the command (report.json): an output file of
  // another option may not take the name. Optional entries (a map written
  // under a name --save-map gives) may.
  bool every_run = true;
};

struct OutputFolderLayout {
  std::string description;                 // "an earlier replay output"
  std::vector<OutputFolderEntry> entries;  // the first match decides
};

OutputFolderEntry file_entry(std::string pattern, OutputFileKind kind, bool every_run = true);
OutputFolderEntry folder_entry(std::string pattern, std::shared_ptr<const OutputFolderLayout> layout,
                               bool every_run = true);

// What is wrong with `folder` as an earlier output laid out as `layout`:
// empty when every entry below it is one (or it is empty), else the first
// entry that is not, with the reason ("'notes.txt', which replay does not
// write"). Symbolic links are never an output's.
std::string foreign_entry(const std::filesystem::path& folder, const OutputFolderLayout& layout);

// The path as the file system sees it: absolute, symbolic links of its
// existing part followed (std::filesystem::weakly_canonical), never throws.
std::filesystem::path resolved_path(const std::filesystem::path& path);
// `path` is `folder` or lies below it (both resolved first).
bool lies_within(const std::filesystem::path& path, const std::filesystem::path& folder);

// One run's inputs and outputs; check() applies the rules above and throws
// an Error naming the path and the option at the first one broken.
class OutputPlan {
 public:
  // A file or folder the run reads (`option` names it: "--gt", "SEQUENCE").
  void input(const std::filesystem::path& path, std::string option);
  // A folder every file of which the run reads (an image folder): no output
  // file may be put directly in it either.
  void input_folder_read_whole(const std::filesystem::path& folder, std::string option);
  void output_file(const std::filesystem::path& path, std::string option, OutputFileKind kind);
  void output_folder(const std::filesystem::path& path, std::string option,
                     std::shared_ptr<const OutputFolderLayout> layout);
  void check() const;

 private:
  struct Input {
    std::filesystem::path path, resolved;
    std::string option;
    bool read_whole = false;
  };
  struct Output {
    std::filesystem::path path, resolved;
    std::string option;
    OutputFileKind kind;                               // a file
    std::shared_ptr<const OutputFolderLayout> layout;  // or a folder
  };
  void check_against_inputs(const Output& output) const;
  void check_against_outputs(const Output& output, std::size_t index) const;
  static void check_existing(const Output& output);
  std::vector<Input> inputs_;
  std::vector<Output> outputs_;
};

}  // namespace facadeslam
