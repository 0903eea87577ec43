/*
 * texgen_ref.h - an independent double-precision evaluation of texture coordinate
 * generation (§2.11.4) and the texture matrix, on matrices read back from GL (the values
 * GL stored, as column-major doubles). Per vertex: eye = M o; the eye normal
 * n = normalize(n (M^-1)) (upper 3x3, the normal a row vector; normalized as with
 * GL_NORMALIZE); u = normalize(eye); r = u - 2 n (n . u); sphere map
 * m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2), (s, t) = (rx / m + 1/2, ry / m + 1/2); an eye
 * plane given under modelview M_p is p M_p^-1. Include after ffl_test.h.
 */
#ifndef FFL_TEXGEN_REF_H
#define FFL_TEXGEN_REF_H

/* m: 16 doubles of a matrix GL stored (glGetFloatv of GL_MODELVIEW_MATRIX, ...). */
static inline void tref_read_matrix(GLenum pname, double *m)
{
    GLfloat f[16];
    int k;
    glGetFloatv(pname, f);
    for (k = 0; k < 16; k++)
        m[k] = f[k];
}

/* out = m v (column-major m). */
static inline void tref_mul(const double *m, const double *v, double *out)
{
    int r;
    for (r = 0; r < 4; r++)
        out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
}

/* The inverse of a column-major 4x4 matrix, by Gauss-Jordan elimination with pivoting. */
static inline void tref_invert(const double *m, double *inv)
{
    double a[4][8];
    int r, c, k;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 8; c++)
            a[r][c] = c < 4 ? m[c * 4 + r] : (c - 4 == r);
    for (c = 0; c < 4; c++) {
        int pivot = c;
        for (r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[pivot][c]))
                pivot = r;
        for (k = 0; k < 8; k++) {
            double t = a[c][k];
            a[c][k] = a[pivot][k];
            a[pivot][k] = t;
        }
        for (k = 7; k >= c; k--)
            a[c][k] /= a[c][c];
        for (r = 0; r < 4; r++)
            if (r != c)
                for (k = 7; k >= c; k--)
                    a[r][k] -= a[r][c] * a[c][k];
    }
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            inv[c * 4 + r] = a[r][4 + c];
}

/* p M^-1 for the row vector p: the eye-space plane of a plane given under M. */
static inline void tref_eye_plane(const GLfloat *p, const double *m, double *out)
{
    double inv[16];
    int c;
    tref_invert(m, inv);
    for (c = 0; c < 4; c++)
        out[c] = p[0] * inv[c * 4] + p[1] * inv[c * 4 + 1] + p[2] * inv[c * 4 + 2] +
                 p[3] * inv[c * 4 + 3];
}

static inline double tref_dot4(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* What generation needs of one vertex under `modelview`: its eye position, unit eye
 * normal, reflection vector and sphere map coordinates (s, t). */
typedef struct {
    double eye[4], normal[3], reflection[3], sphere[2];
} tref_vertex;

static inline void tref_vertex_terms(const double *modelview, const double *object,
                                     const GLfloat *normal, tref_vertex *v)
{
    double inv[16], u[3], len, nu, m;
    int k;
    tref_mul(modelview, object, v->eye);
    tref_invert(modelview, inv);
    for (k = 0; k < 3; k++)
        v->normal[k] = normal[0] * inv[k * 4] + normal[1] * inv[k * 4 + 1] +
                       normal[2] * inv[k * 4 + 2];
    len = sqrt(v->normal[0] * v->normal[0] + v->normal[1] * v->normal[1] +
               v->normal[2] * v->normal[2]);
    for (k = 0; k < 3; k++)
        v->normal[k] /= len;
    len = sqrt(v->eye[0] * v->eye[0] + v->eye[1] * v->eye[1] + v->eye[2] * v->eye[2]);
    for (k = 0; k < 3; k++)
        u[k] = v->eye[k] / len;
    nu = v->normal[0] * u[0] + v->normal[1] * u[1] + v->normal[2] * u[2];
    for (k = 0; k < 3; k++)
        v->reflection[k] = u[k] - 2.0 * v->normal[k] * nu;
    m = 2.0 * sqrt(v->reflection[0] * v->reflection[0] + v->reflection[1] * v->reflection[1] +
                   (v->reflection[2] + 1.0) * (v->reflection[2] + 1.0));
    v->sphere[0] = v->reflection[0] / m + 0.5;
    v->sphere[1] = v->reflection[1] / m + 0.5;
}

#endif /* FFL_TEXGEN_REF_H */
