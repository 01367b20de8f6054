// A canonical hash of a simulation state, the same on every machine that
// computes the same doubles: FNV-1a 64 over the canonical bytes of each
// number (docs/determinism.md). `particles run --hash` prints it for the
// final state; the suite hashes its results with the same primitives.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "particles/world.h"

namespace particles {

// FNV-1a, 64-bit: offset basis 0xcbf29ce484222325, prime 0x100000001b3,
// one byte at a time.
class StateHasher {
 public:
  void addByte(std::uint8_t byte) {
    hash_ ^= byte;
    hash_ *= 0x100000001b3ULL;
  }
  // The 8 bytes of `value`, least significant first (little-endian on
  // every host, so big-endian machines agree).
  void addU64(std::uint64_t value) {
    for (int i = 0; i < 8; ++i) addByte(static_cast<std::uint8_t>(value >> (8 * i)));
  }
  // The IEEE-754 bits of `value` as addU64, canonicalised first: -0.0 as
  // +0.0, and every NaN or infinity as the quiet NaN 0x7ff8000000000000
  // (JSON writes them all as null, so a report read back hashes the same).
  void addDouble(double value);

  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// Per ball, in order: position x, y, velocity x, y, angle, angular velocity
// (addDouble each). Time and scene are not included.
std::uint64_t stateHash(std::span<const BallState> balls);
std::uint64_t stateHash(const World& world);

// 16 lowercase hex digits, most significant first.
std::string hashHex(std::uint64_t hash);

}  // namespace particles
