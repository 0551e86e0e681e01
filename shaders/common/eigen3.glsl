// Cyclic Jacobi eigen-decomposition of a symmetric 3x3 matrix: the algorithm
// of common/eigen3.c in single precision. On return eval is ascending and
// column k of evec is the unit eigenvector of eval[k].
void fs_eigen3_sym(mat3 a, out vec3 eval, out mat3 evec)
{
    mat3 v = mat3(1.0);
    for (int sweep = 0; sweep < 8; sweep++) {
        float off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        float diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-14 * diag || off == 0.0) break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                float apq = a[p][q];
                if (apq == 0.0) continue;
                float theta = (a[q][q] - a[p][p]) / (2.0 * apq);
                float t = (theta >= 0.0 ? 1.0 : -1.0) / (abs(theta) + sqrt(theta * theta + 1.0));
                float c = inversesqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; k++) {
                    float akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) {
                    float apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    float vkp = v[p][k], vkq = v[q][k]; // columns of v are eigenvectors
                    v[p][k] = c * vkp - s * vkq;
                    v[q][k] = s * vkp + c * vkq;
                }
            }
    }
    vec3 e = vec3(a[0][0], a[1][1], a[2][2]);
    ivec3 o = ivec3(0, 1, 2);
    if (e[o.y] < e[o.x]) o.xy = o.yx;
    if (e[o.z] < e[o.y]) o.yz = o.zy;
    if (e[o.y] < e[o.x]) o.xy = o.yx;
    eval = vec3(e[o.x], e[o.y], e[o.z]);
    evec = mat3(v[o.x], v[o.y], v[o.z]);
}
