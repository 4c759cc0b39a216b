#include "algorithm/precision_loss.hpp"

namespace cmx::algorithm {

namespace {

std::string phase_phrase(const std::string& phase) {
  const std::string split = " (split)";
  if (phase.size() > split.size() && phase.ends_with(split))
    return "a split during " + phase_phrase(phase.substr(0, phase.size() - split.size()));
  if (phase == "input") return "reading the input";
  if (phase == "shrink") return "the shrink";
  if (phase == "verification") return "the final verification";
  if (phase == "simple") return "a simple expansion";
  if (phase == "star-shapified") return "a star-shapification";
  if (phase == "inflation") return "an inflation";
  if (phase == "automatic") return "an automatic expansion";
  return "a " + phase;  // refinement, "<kind> (split)"
}

}  // namespace

std::string PrecisionLoss::message() const {
  std::string m = "validity lost in " + phase_phrase(phase);
  if (phase != "input" && phase != "shrink") m += " after " + std::to_string(step) + " expansions";
  if (!what.empty()) m += ": " + what;
  if (tet) {
    m += "; tet (" + std::to_string((*tet)[0]) + ", " + std::to_string((*tet)[1]) + ", " + std::to_string((*tet)[2]) +
         ", " + std::to_string((*tet)[3]) + ") is " + (orientation == Sign::zero ? "degenerate" : "inverted") + " in the " +
         (in_source ? "source" : "target");
  }
  if (exact_bits) m += "; the exact position had " + std::to_string(exact_bits) + "-bit coordinates";
  return m;
}

PrecisionLost::PrecisionLost(PrecisionLoss loss) : std::runtime_error(loss.message()), loss_(std::move(loss)) {}

}  // namespace cmx::algorithm
