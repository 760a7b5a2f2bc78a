#pragma once
// The files the program ships with (models/, configs/, the embedded demo in
// data/demo/), found from where the executable is, never from the current
// folder: `facadeslam replay` run from any folder uses the same model and
// settings as run from the project's own.
#include <filesystem>

namespace facadeslam {

// `relative` (e.g. "models/default.fsmodel") under the first of these
// folders that holds it: $FACADESLAM_HOME; the folder above the executable's
// (the build tree: build/facadeslam -> the checkout); <prefix>/share/facadeslam
// beside an installed bin/facadeslam. When none holds it, the path under the
// first of them (so that a message names where it was expected).
std::filesystem::path shipped_file(const std::filesystem::path& relative);

}  // namespace facadeslam
