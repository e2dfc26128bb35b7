/* Builds against an installed se23 (CMake package or pkg-config) and checks
 * one call, to prove the installed headers, library and flags work. */
#include <stdio.h>

#include "se23/se23.h"

int main(void)
{
    se23_tangent_t xi = {{0.1, 0.2, 0.3, 1, 2, 3, 4, 5, 6}};
    se23_tangent_t back;
    se23_pose_t T;
    if (se23_exp(&xi, &T) != SE23_OK || se23_log(&T, &back) != SE23_OK) {
        return 1;
    }
    printf("se23 consumer: sizeof(se23_real_t) = %u, log(exp(xi))[8] = %g\n",
           (unsigned)sizeof(se23_real_t), (double)back.v[8]);
    return 0;
}
