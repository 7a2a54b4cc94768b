#include "knife_edge_watch.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string_view>

namespace cutcom::props {

nlohmann::json knife_edge_baseline(const CampaignSummary& s) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [clause, n] : s.knife_edges) counts[clause] = n;
  nlohmann::json ending = nlohmann::json::object();
  for (const auto& [clause, n] : s.knife_edges_ending_differently) ending[clause] = n;
  return {{"seed", s.seed}, {"cases", s.cases}, {"knife_edges", counts}, {"ending_differently", ending}};
}

std::vector<std::string> knife_edge_rises(const CampaignSummary& s, const nlohmann::json& baseline) {
  if (!baseline.is_object() || !baseline.contains("cases") || !baseline.contains("knife_edges") ||
      !baseline["cases"].is_number_integer() || !baseline["knife_edges"].is_object() ||
      baseline["cases"].get<long>() < 1)
    throw std::runtime_error("a knife-edge baseline needs \"cases\" (at least 1) and \"knife_edges\" {clause: count}");
  if (baseline.contains("ending_differently") && !baseline["ending_differently"].is_object())
    throw std::runtime_error("a knife-edge baseline's \"ending_differently\" must be {clause: count}");
  const double scale = static_cast<double>(s.cases) / static_cast<double>(baseline["cases"].get<long>());
  std::vector<std::string> rises;
  auto watch = [&](const std::map<std::string, long>& counts, const nlohmann::json& base, std::string_view what) {
    for (const auto& [clause, n] : counts) {
      long before = 0;
      if (auto it = base.find(clause); it != base.end()) {
        if (!it->is_number_integer())
          throw std::runtime_error(fmt::format("knife-edge baseline: {} is not a count", clause));
        before = it->get<long>();
      }
      double expected = static_cast<double>(before) * scale;
      double allowed = expected + 3 * std::sqrt(expected) + 3;
      if (static_cast<double>(n) > allowed)
        rises.push_back(fmt::format("{}: {} {} in {} cases, baseline {} in {} (at most {:.0f} allowed)", clause, n,
                                    what, s.cases, before, baseline["cases"].get<long>(), std::floor(allowed)));
    }
  };
  watch(s.knife_edges, baseline["knife_edges"], "knife edges");
  if (baseline.contains("ending_differently"))
    watch(s.knife_edges_ending_differently, baseline["ending_differently"], "knife edges ending differently");
  return rises;
}

}  // namespace cutcom::props
