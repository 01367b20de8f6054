#include "suite_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "particles/html/document.h"

namespace particles::cli {
namespace {

// Exact agreement (0) is drawn here on the log axis.
constexpr double kFloor = 1e-17;

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return NAN;
  const std::size_t i = static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5);
  return sorted[std::min(i, sorted.size() - 1)];
}

// The empirical distribution function of `values` (sorted): fraction of
// cases with a discrepancy <= x, at most ~200 points.
std::vector<std::pair<double, double>> cdf(const std::vector<double>& sorted) {
  std::vector<std::pair<double, double>> pts;
  const std::size_t n = sorted.size(), stride = std::max<std::size_t>(1, n / 200);
  for (std::size_t i = 0; i < n; i += stride)
    pts.push_back(
        {std::max(sorted[i], kFloor), static_cast<double>(i + 1) / static_cast<double>(n)});
  if (n > 0) pts.push_back({std::max(sorted.back(), kFloor), 1.0});
  return pts;
}

}  // namespace

void writeSuiteHtml(const std::filesystem::path& dir, const compare::SuiteResult& result) {
  std::map<compare::Family, std::vector<double>> engine, box2d;
  std::map<compare::Family, int> cases, failed;
  for (const compare::CaseRecord& c : result.cases) {
    const compare::Family f = c.kase.family;
    ++cases[f];
    failed[f] += !c.pass;
    if (c.engineTruth) engine[f].push_back(c.engineTruth->relative);
    box2d[f].push_back(c.attribution.discrepancy.relative);
  }
  html::Document doc("particles suite: engine, closed form and Box2D");
  doc.paragraph(std::string(result.passed() ? "PASS" : "FAIL") + ": " +
                std::to_string(result.cases.size()) + " cases, " + std::to_string(result.failed()) +
                " failed, " + std::to_string(result.unexplained()) +
                " unexplained Box2D discrepancies. Details per case: report.md and report.json "
                "(docs/report-format.md).");
  doc.paragraph(
      "Relative discrepancy (dimensionless): over the balls, the largest of |dv| and |dw| r, "
      "divided by the case's speed scale. Engine: against the closed form (isolated cases "
      "only). Box2D: against the reference answer (the closed form where there is one, else "
      "the engine).");
  html::Table t{"Per family",
                {"family", "cases", "failed", "engine median", "engine worst", "Box2D median",
                 "Box2D 99 %", "Box2D worst"},
                {},
                {}};
  for (compare::Family f : compare::kAllFamilies) {
    std::vector<double>& e = engine[f];
    std::vector<double>& b = box2d[f];
    std::sort(e.begin(), e.end());
    std::sort(b.begin(), b.end());
    auto q = [](const std::vector<double>& v, double p) {
      return v.empty() ? "n/a" : sci(quantile(v, p));
    };
    t.rows.push_back({std::string(compare::familyName(f)), std::to_string(cases[f]),
                      std::to_string(failed[f]), q(e, 0.5), q(e, 1.0), q(b, 0.5), q(b, 0.99),
                      q(b, 1.0)});
    t.rowClass.push_back(failed[f] == 0 ? "good" : "bad");
  }
  doc.table(t);
  for (int k = 0; k < 2; ++k) {
    html::Plot p;
    p.title = k == 0 ? "Engine against the closed form: distribution per family"
                     : "Box2D against the reference: distribution per family";
    p.xLabel = "relative discrepancy (exact agreement drawn at 1e-17)";
    p.yLabel = "fraction of cases <= x";
    p.logX = true;
    int color = 0;
    for (compare::Family f : compare::kAllFamilies) {
      const std::vector<double>& v = (k == 0 ? engine : box2d)[f];
      if (!v.empty())
        p.series.push_back({std::string(compare::familyName(f)), cdf(v), "lines", 7, color});
      ++color;
    }
    doc.plot(p);
  }
  doc.write(dir);
}

}  // namespace particles::cli
