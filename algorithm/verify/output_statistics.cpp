#include "algorithm/verify/output_statistics.hpp"

#include <algorithm>

namespace cmx::algorithm {

void output_statistics(std::size_t tets, const std::vector<HPoint>& target, MapStatistics& s) {
  s.output_vertices = target.size();
  s.output_tets = tets;
  s.growth_ratio = double(s.output_vertices) / double(s.input_vertices);
  double total = 0;
  for (const HPoint& p : target) {
    s.max_bits = std::max(s.max_bits, p.bit_size());
    total += double(p.bit_size());
  }
  s.mean_bits = target.empty() ? 0 : total / double(target.size());
}

}  // namespace cmx::algorithm
