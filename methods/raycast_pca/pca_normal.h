/* xiao2017 3.3 on the CPU: the basic SPH-gradient normal (eq. 2, spiky kernel
 * of radius R), the PCA normal (eqs. 3-4, weight 1 - (d/R)^3, Jacobi) and their
 * blend (eqs. 5-6). shaders/raycast_pca/normals.comp.glsl computes the same;
 * the tests call these to check the maths on known point sets. */
#ifndef FS_RPCA_PCA_NORMAL_H
#define FS_RPCA_PCA_NORMAL_H
#ifdef __cplusplus
extern "C" {
#endif

typedef enum { RPCA_NORMALS_BASIC = 0, RPCA_NORMALS_PCA, RPCA_NORMALS_BLEND } rpca_normals;

typedef struct rpca_normal_opts {
    int mode;            /* RPCA_NORMALS_* */
    float R;             /* neighbourhood radius, scene units */
    int min_neighbors;   /* fewer inside R: fall back to the basic normal */
    int fixed_weight;    /* 1: w = w_fixed; 0: eq. 6 */
    float w_fixed, d, k; /* eq. 5-6 */
} rpca_normal_opts;

/* Outward normal -sum grad W_spiky(x - p_j, R), normalised; 0 when undefined. */
int rpca_basic_normal(const float x[3], const float *pts, int n, float R, float out[3]);
/* Smallest-eigenvalue eigenvector of the weighted covariance around x, sign
 * unset. Returns 0 when it is undefined: fewer than min_n points inside R or a
 * covariance of rank < 2 (points on a line or one point: no unique plane). */
int rpca_pca_normal(const float x[3], const float *pts, int n, float R, int min_n, float out[3]);
/* eq. 6's weight for unit basic b and PCA p normals. */
float rpca_blend_weight(const rpca_normal_opts *o, const float b[3], const float p[3]);
/* The normal by o->mode with the fallbacks of 3.3. Returns 1 when PCA was
 * used, 0 for the basic normal alone, -1 when no normal is defined. */
int rpca_normal(const float x[3], const float *pts, int n, const rpca_normal_opts *o, float out[3]);

#ifdef __cplusplus
}
#endif
#endif
