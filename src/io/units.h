#pragma once
// The one place where edge units (files, UI: millimetres, GPa, g/cm3,
// degrees) become SI and back. Nothing else in coilsim converts units.
#include <cmath>

#include "physics/param.h"

namespace coilsim::units {

inline constexpr double kMetresPerMm = 1e-3;
inline constexpr double kPaPerGPa = 1e9;
inline constexpr double kKgM3PerGCm3 = 1e3;
inline constexpr double kRadPerDeg = M_PI / 180.0;

inline constexpr double mmToM(double mm) { return mm * kMetresPerMm; }
inline constexpr double mToMm(double m) { return m / kMetresPerMm; }
inline constexpr double gpaToPa(double gpa) { return gpa * kPaPerGPa; }
inline constexpr double paToGpa(double pa) { return pa / kPaPerGPa; }
inline constexpr double gcm3ToKgm3(double g) { return g * kKgM3PerGCm3; }
inline constexpr double kgm3ToGcm3(double k) { return k / kKgM3PerGCm3; }
inline constexpr double degToRad(double d) { return d * kRadPerDeg; }
inline constexpr double radToDeg(double r) { return r / kRadPerDeg; }

// Derived edge units of scene files: areas, second moments, moments, rates.
inline constexpr double mm2ToM2(double mm2) { return mm2 * kMetresPerMm * kMetresPerMm; }
inline constexpr double mm4ToM4(double mm4) { return mm2ToM2(mm2ToM2(mm4)); }
inline constexpr double nmmToNm(double nmm) { return nmm * kMetresPerMm; }
inline constexpr double nmToNmm(double nm) { return nm / kMetresPerMm; }
inline constexpr double mmPerSToMPerS(double v) { return v * kMetresPerMm; }
inline constexpr double degPerSToRadPerS(double w) { return w * kRadPerDeg; }
inline constexpr double degPerMmToRadPerM(double t) { return t * kRadPerDeg / kMetresPerMm; }

// What the panels, reports and result files show besides. Areas and
// volumes in mm2 and mm3 (as the lengths); penetrations in micrometres,
// forces in millinewtons (the unit clinical force papers report), times in
// milliseconds and the timings of runs and benches in microseconds multiply
// by the exact power of ten (1e3, 1e6), and back by its inverse (as mmToM).
inline constexpr double m2ToMm2(double m2) { return mToMm(mToMm(m2)); }
inline constexpr double m3ToMm3(double m3) { return mToMm(mToMm(mToMm(m3))); }
inline constexpr double mToUm(double m) { return m * 1e6; }
inline constexpr double nToMn(double n) { return n * 1e3; }
inline constexpr double mnToN(double mn) { return mn * 1e-3; }
inline constexpr double sToMs(double s) { return s * 1e3; }
inline constexpr double sToUs(double s) { return s * 1e6; }
inline constexpr double nsToUs(double ns) { return ns * 1e-3; }  // a clock's nanoseconds (timespec::tv_nsec)

// A declared parameter (effect or rod quantity) between its edge unit and SI.
inline constexpr double toSI(const ParamSpec& p, double edge) { return edge * p.toSI; }
inline constexpr double fromSI(const ParamSpec& p, double si) { return si / p.toSI; }

}  // namespace coilsim::units
