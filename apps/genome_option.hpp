#pragma once
// The --genome option shared by the semantic commands: a genome file (0/1
// text or .json), the 211-character 0/1 string itself, or empty for the
// thesis' best genome.
#include <string>

#include "semantics/descriptor/genome.hpp"

namespace facadeslam::apps {

// Throws Error naming --genome when the value is neither a file nor a
// genome string.
semantics::Genome resolve_genome(const std::string& value);

}  // namespace facadeslam::apps
