// The one translation unit that includes Eigen's MatrixFunctions (slow to
// compile): generic matrix exponential and principal logarithm, dynamic size,
// double and long double. See reference.hpp.
#include <unsupported/Eigen/MatrixFunctions>

#include "reference.hpp"

namespace se23ref {

MatX expm(const MatX &A) { return A.exp(); }
MatXL expm(const MatXL &A) { return A.exp(); }
MatX logm(const MatX &A) { return A.log(); }
MatXL logm(const MatXL &A) { return A.log(); }

} // namespace se23ref
