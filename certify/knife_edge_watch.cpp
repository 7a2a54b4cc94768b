#include "knife_edge_watch.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace cutcom::props {

nlohmann::json knife_edge_baseline(const CampaignSummary& s) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [clause, n] : s.knife_edges) counts[clause] = n;
  return {{"seed", s.seed}, {"cases", s.cases}, {"knife_edges", counts}};
}

std::vector<std::string> knife_edge_rises(const CampaignSummary& s, const nlohmann::json& baseline) {
  if (!baseline.is_object() || !baseline.contains("cases") || !baseline.contains("knife_edges") ||
      !baseline["cases"].is_number_integer() || !baseline["knife_edges"].is_object() ||
      baseline["cases"].get<long>() < 1)
    throw std::runtime_error("a knife-edge baseline needs \"cases\" (at least 1) and \"knife_edges\" {clause: count}");
  const double scale = static_cast<double>(s.cases) / static_cast<double>(baseline["cases"].get<long>());
  std::vector<std::string> rises;
  for (const auto& [clause, n] : s.knife_edges) {
    long before = 0;
    if (auto it = baseline["knife_edges"].find(clause); it != baseline["knife_edges"].end()) {
      if (!it->is_number_integer())
        throw std::runtime_error(fmt::format("knife-edge baseline: {} is not a count", clause));
      before = it->get<long>();
    }
    double expected = static_cast<double>(before) * scale;
    double allowed = expected + 3 * std::sqrt(expected) + 3;
    if (static_cast<double>(n) > allowed)
      rises.push_back(fmt::format("{}: {} knife edges in {} cases, baseline {} in {} (at most {:.0f} allowed)", clause,
                                  n, s.cases, before, baseline["cases"].get<long>(), std::floor(allowed)));
  }
  return rises;
}

}  // namespace cutcom::props
