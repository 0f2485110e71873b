// The rope of issue 36, written as a student would: `links` springs (k = 200 N/m) joining
// 0.1 kg point nodes 0.5 m apart, laid out level from node n0, which is fixed; it falls and
// swings under gravity. A game's step is far too long for its springs written by hand, and
// an engine's springs must hold it up however they are built.
#pragma once

#include <string>

namespace bb::test {

inline constexpr int kRopeLinks = 6;
inline constexpr double kRopeStiffness = 200.0;  ///< N/m
inline constexpr double kRopeNodeMass = 0.1;     ///< kg
inline constexpr double kRopeLink = 0.5;         ///< m, each link's rest length
inline constexpr double kRopeHeight = 10.0;      ///< m, where it hangs from

/// The rope's case, 2D, sampled every 0.25 s over `duration` s at steps `dts` ("[0.25]").
inline std::string rope_case(const std::string& dts, double duration = 4.0) {
  std::string text = "name = \"rope\"\ndims = 2\nduration = " + std::to_string(duration) +
                     "\nsample = 0.25\ndt = " + dts +
                     "\nreport_dt = " + dts.substr(1, dts.find_first_of(",]") - 1) + "\n";
  for (int i = 0; i <= kRopeLinks; ++i)
    text += "[[body]]\nname = \"n" + std::to_string(i) +
            "\"\nshape = \"point\"\nmass = " + std::to_string(kRopeNodeMass) + "\n" +
            (i == 0 ? "fixed = true\n" : "") + "position = [" + std::to_string(i * kRopeLink) +
            ", " + std::to_string(kRopeHeight) + ", 0.0]\n";
  for (int i = 1; i <= kRopeLinks; ++i)
    text += "[[spring]]\nbodies = [\"n" + std::to_string(i - 1) + "\", \"n" + std::to_string(i) +
            "\"]\nstiffness = " + std::to_string(kRopeStiffness) + "\n";
  return text;
}

}  // namespace bb::test
