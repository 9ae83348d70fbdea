#pragma once
// Rules every command's options meet, applied once to the whole command line in main() rather than
// option by option: number options refuse what no range check can see, and an error about an
// option shows the value as it was typed.
#include <CLI/CLI.hpp>

#include "aerial/error.h"

namespace aerial::cli {

// Every floating-point option of every command of app refuses NaN and infinity (and a value whose
// magnitude overflows a double) with Error(option, the value as typed, "a finite number"): NaN
// passes any range check, as every comparison with it is false (`--target-ms nan` would have
// turned dynamic resolution off), and infinity breaks the arithmetic that follows. Call it once
// every command's options are added.
void RefuseNonFiniteNumbers(CLI::App& app);

// e, or, when e names an option of a parsed command of app that was given one value which reads as
// the same number as e's value, e with the value as the user typed it ("6e4", not "60000").
Error AsTyped(const Error& e, const CLI::App& app);

}  // namespace aerial::cli
