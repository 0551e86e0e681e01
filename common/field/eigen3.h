/* Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations
 * (xiao2017 3.3; the anisotropic kernels of yu2013/xu2022 need it too).
 * shaders/common/eigen3.glsl holds the same algorithm for shaders. */
#ifndef FS_EIGEN3_H
#define FS_EIGEN3_H
#ifdef __cplusplus
extern "C" {
#endif

/* a: symmetric matrix, row-major a[3*i+j] (only the upper triangle is read).
 * On return eval[0] <= eval[1] <= eval[2] and evec[3*k .. 3*k+2] is the unit
 * eigenvector of eval[k]. Returns the number of sweeps used (at most 16). */
int fs_eigen3_sym(const double a[9], double eval[3], double evec[9]);

#ifdef __cplusplus
}
#endif
#endif
