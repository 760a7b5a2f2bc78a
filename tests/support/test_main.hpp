#pragma once
// The exit code of a test program whose selected tests all skipped; CTest's
// SKIP_RETURN_CODE (cmake/FacadeslamTargets.cmake) says the same number.
namespace facadeslam::test {
inline constexpr int kAllSkippedExitCode = 77;
}  // namespace facadeslam::test
