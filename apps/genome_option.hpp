#pragma once
// The --genome option shared by the semantic commands: a genome file (0/1
// text or .json), the 211-character 0/1 string itself, or empty for the
// thesis' best genome.
#include <string>

#include "semantics/descriptor/genome.hpp"

namespace facadeslam::apps {

// Throws CLI::ValidationError (a bad command line, exit code 2) naming
// `option` when the value is neither a file nor a valid genome string, and
// Error (exit code 1) for a genome file that does not parse.
semantics::Genome resolve_genome(const std::string& value, const std::string& option = "--genome");

}  // namespace facadeslam::apps
