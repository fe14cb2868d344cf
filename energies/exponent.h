#pragma once
// The exponent k of the exponential energies (exp(k u)), checked once for
// every energy that has one, 2D and 3D.
#include "framework/process/error.h"

namespace akvf {

inline double checked_exponent(double k) {
  if (!(k > 0)) throw OptionsError("energy exponent must be > 0");
  return k;
}

}  // namespace akvf
