// A user's extension of the Python module, as docs/python.md describes it:
// built against akvf's headers alone, loaded with akvf.load_extension(path).
// Registers a 2D energy written only as its density: symmetric Dirichlet
// plus an area term, minimum 4 at rotations.
#include "akvf/extend.h"

namespace {

struct AreaSymmetricDirichlet {
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    const T det = J.determinant();
    return J.squaredNorm() * (T(1) + T(1) / (det * det)) + (det - T(1)) * (det - T(1));
  }
};

}  // namespace

extern "C" void akvf_register_extension() {
  akvf::register_autodiff_energy<2>("area-symmetric-dirichlet", "|J|^2 + |J^-1|^2 + (det J - 1)^2 (a test extension)",
                                    4.0, AreaSymmetricDirichlet{});
}
