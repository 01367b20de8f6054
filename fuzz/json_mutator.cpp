// A structure-aware mutator: half of the mutations parse the input as JSON,
// change one value the way a scene author could (an extreme number, a wrong
// type, a missing or extra key, a copied ball) and print it again, so that
// most inputs get past the parser and reach the checks and the solver. The
// other half are libFuzzer's byte mutations (with fuzz/scene.dict), which
// find the parser's own problems.
#include <array>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

using nlohmann::json;
using Rng = std::minstd_rand;

// Numbers at the edges of what the loader accepts or a double holds.
constexpr std::array<double, 22> kNumbers{
    0.0, -0.0, 1e-300, -1e-300, 5e-324, 1e300,  -1e300,       1e308,  1e-6,  1e6,   -1.0,
    0.5, 1.0,  2.0,    1e12,    1e-12,  4.9e-9, 2147483647.0, 9.3e18, 3e-13, 100.0, 1e15};

constexpr std::array<double, 10> kScales{1e-300, 1e-12, 1e-6, 0.5,   1.0 + 1e-9,
                                         2.0,    1e6,   1e12, 1e300, 1.0 - 1e-9};

constexpr std::array<const char*, 33> kKeys{"name",
                                            "gravity",
                                            "contact",
                                            "walls",
                                            "box",
                                            "balls",
                                            "forces",
                                            "dt",
                                            "duration",
                                            "solver",
                                            "position",
                                            "velocity",
                                            "angle",
                                            "angular_velocity",
                                            "radius",
                                            "mass",
                                            "inertia",
                                            "restitution",
                                            "friction",
                                            "a",
                                            "b",
                                            "min",
                                            "max",
                                            "type",
                                            "ball",
                                            "target",
                                            "stiffness",
                                            "force",
                                            "torque",
                                            "start",
                                            "end",
                                            "contact_passes",
                                            "correction_passes"};

// Legal scenes to restart from now and then: most of the corpus is text the
// loader rejects (every distinct rejection is new coverage), and mutating
// it again rarely gives a scene that reaches the solver.
constexpr std::array<const char*, 3> kLegalScenes{
    R"({"balls": [{"position": [0, 0.5], "velocity": [2, -1], "radius": 0.5, "mass": 1},
                  {"position": [1.2, 0.5], "velocity": [-1, 0], "angular_velocity": 3, "radius": 0.5,
                   "mass": 2, "friction": "infinite"}],
        "walls": [{"a": [-5, 0], "b": [5, 0]}], "gravity": [0, -9.81],
        "contact": {"restitution": 0.5, "friction": 0.3}, "duration": 0.01})",
    R"({"box": {"min": [0, 0], "max": [4, 4]}, "balls": [{"position": [1, 1], "velocity": [3, 1],
        "radius": 0.5, "mass": 1, "inertia": 0.2}, {"position": [2.2, 1], "radius": 0.4, "mass": 1},
        {"position": [3, 3], "velocity": [-2, -2], "radius": 0.5, "mass": 1}],
        "forces": [{"type": "pull", "ball": 0, "target": [2, 2], "stiffness": 10}],
        "solver": {"contact_passes": 16}, "duration": 0.01})",
    R"({"balls": [{"position": [0, 0], "velocity": [1, 0], "radius": 0.5, "mass": 1},
                  {"position": [1, 0], "radius": 0.5, "mass": 1}, {"position": [2, 0], "radius": 0.5, "mass": 1}],
        "forces": [{"type": "constant", "ball": 2, "force": [0, 1], "torque": 0.5, "start": 0, "end": 0.005}],
        "contact": {"restitution": 1, "friction": "infinite"}, "dt": 0.001, "duration": 0.005})",
};

std::size_t pick(Rng& rng, std::size_t n) {
  return static_cast<std::size_t>(rng()) % n;
}

json randomValue(Rng& rng) {
  switch (pick(rng, 8)) {
    case 0:
      return kNumbers[pick(rng, kNumbers.size())];
    case 1:
      return json::array({kNumbers[pick(rng, kNumbers.size())], kNumbers[pick(rng, 8)]});
    case 2:
      return "infinite";
    case 3:
      return pick(rng, 2) ? "pull" : "constant";
    case 4:
      return nullptr;
    case 5:
      return json::object();
    case 6:
      return static_cast<int>(pick(rng, 5)) - 1;
    default:
      return json::array();
  }
}

void collect(json& j, std::vector<json*>& out) {
  out.push_back(&j);
  if (j.is_structured())
    for (json& child : j) collect(child, out);
}

// Changes one value somewhere in `doc`.
void mutate(json& doc, Rng& rng) {
  std::vector<json*> nodes;
  collect(doc, nodes);
  json& j = *nodes[pick(rng, nodes.size())];
  switch (pick(rng, 8)) {
    case 0:  // an edge number
      j = kNumbers[pick(rng, kNumbers.size())];
      break;
    case 7:
    case 1:  // the same sign, another scale: mostly still legal, so it reaches the solver
      if (j.is_number()) j = j.get<double>() * kScales[pick(rng, kScales.size())];
      break;
    case 2:  // any value, any type
      j = randomValue(rng);
      break;
    case 3:  // drop a key or an element
      if (j.is_object() && !j.empty()) {
        auto it = j.begin();
        std::advance(it, static_cast<long>(pick(rng, j.size())));
        j.erase(it);
      } else if (j.is_array() && !j.empty()) {
        j.erase(pick(rng, j.size()));
      }
      break;
    case 4:  // add a known key
      if (j.is_object()) j[kKeys[pick(rng, kKeys.size())]] = randomValue(rng);
      break;
    case 5:  // copy an element, moved so that copied balls need not overlap
      if (j.is_array() && !j.empty()) {
        json copy = j[pick(rng, j.size())];
        if (copy.is_object() && copy.contains("position") && copy["position"].is_array() &&
            copy["position"].size() == 2 && copy["position"][0].is_number())
          copy["position"][0] =
              copy["position"][0].get<double>() + 3.0 * static_cast<double>(j.size());
        j.push_back(copy);
      }
      break;
    default:  // the same element many times (large scenes)
      if (j.is_array() && !j.empty() && j.size() < 64) {
        const json first = j[0];
        const std::size_t n = 1 + pick(rng, 200);
        for (std::size_t i = 0; i < n; ++i) {
          json copy = first;
          if (copy.is_object() && copy.contains("position") && copy["position"].is_array() &&
              copy["position"].size() == 2 && copy["position"][1].is_number())
            copy["position"][1] =
                copy["position"][1].get<double>() + 2.5 * static_cast<double>(i + 1);
          j.push_back(copy);
        }
      }
      break;
  }
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t maxSize, unsigned int seed) {
  Rng rng(seed);
  if (pick(rng, 2) == 0) return LLVMFuzzerMutate(data, size, maxSize);
  json doc = json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || pick(rng, 8) == 0) {
    if (pick(rng, 2) == 0) return LLVMFuzzerMutate(data, size, maxSize);
    doc = json::parse(kLegalScenes[pick(rng, kLegalScenes.size())]);
  }
  for (std::size_t n = pick(rng, 4) == 0 ? 2 : 1; n > 0; --n) mutate(doc, rng);
  const std::string text = doc.dump();
  if (text.size() > maxSize) return LLVMFuzzerMutate(data, size, maxSize);
  std::memcpy(data, text.data(), text.size());
  return text.size();
}
