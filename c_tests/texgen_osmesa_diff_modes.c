/* ffl-test: osmesa-diff */
/*
 * Texture coordinate generation (§2.11.4) and the texture matrix, through feedback
 * (GL_4D_COLOR_TEXTURE), against this program's own double-precision evaluation of the
 * spec. OSMesa's feedback returns the current texture coordinates, neither generated nor
 * transformed (docs/osmesa-differences.md, 19): only the fflight build is checked.
 *
 * Two settings of the four coordinates, each drawn as points with glBegin/glEnd and again
 * with glDrawArrays (12 points: the batch engine's block path), under a modelview made of a
 * translation, a rotation and a non-uniform scale, with GL_NORMALIZE, and a texture matrix
 * that is not the identity:
 *   A: s object linear, t eye linear (its plane given under another modelview), r
 *      reflection map, q object linear;
 *   B: s and t sphere map, r normal map, q eye linear.
 * Then two state queries where OSMesa departs from the spec: glGetTexGeniv of an eye plane
 * that is not integral (§6.1.2: rounded to the nearest integer; OSMesa truncates) and
 * glTexGenf with a plane pname (not a single-valued parameter: GL_INVALID_ENUM, plane
 * unchanged; OSMesa sets the plane to (param, 0, 0, 0)).
 *
 * The reference reads the matrices back with glGetDoublev-free glGetFloatv (the values GL
 * stored) and evaluates, per vertex: eye = M o; n = normalize((M^-1)^T n) (upper 3x3);
 * u = normalize(eye); r = u - 2 n (n . u); eye plane = p M_p^-1 (M_p the modelview when the
 * plane was given); then the texture matrix.
 */
#include "ffl_test.h"

#define POINTS 12
#define BUF_SIZE 4096

static double modelview[16], plane_modelview[16], texture_matrix[16];
static GLfloat object[POINTS][4], normals[POINTS][3], currents[POINTS][4];
static const GLfloat object_plane_s[4] = { 0.5f, -1.25f, 2.0f, 0.25f };
static const GLfloat object_plane_q[4] = { -0.75f, 0.5f, 0.125f, 1.5f };
static const GLfloat eye_plane_t[4] = { 1.5f, 0.25f, -0.5f, 0.75f };
static const GLfloat eye_plane_q[4] = { 0.25f, 1.0f, 0.5f, -0.25f };
static int setting, noted;

static void read_matrix(GLenum pname, double *m)
{
    GLfloat f[16];
    int k;
    glGetFloatv(pname, f);
    for (k = 0; k < 16; k++)
        m[k] = f[k];
}

/* out = m v (column-major m). */
static void mul(const double *m, const double *v, double *out)
{
    int r;
    for (r = 0; r < 4; r++)
        out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
}

/* The inverse of a column-major 4x4 matrix, by Gauss-Jordan elimination with pivoting. */
static void invert(const double *m, double *inv)
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

/* p M^-1 for the row vector p: the eye-space plane. */
static void eye_plane(const GLfloat *p, const double *m, double *out)
{
    double inv[16];
    int c;
    invert(m, inv);
    for (c = 0; c < 4; c++)
        out[c] = p[0] * inv[c * 4] + p[1] * inv[c * 4 + 1] + p[2] * inv[c * 4 + 2] +
                 p[3] * inv[c * 4 + 3];
}

static double dot4(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* The spec's texture coordinates of vertex i in the current setting. */
static void reference(int i, double *out)
{
    double o[4], e[4], inv[16], n[3], u[3], r[3], g[4], plane[4], len, nu, m;
    int k;
    for (k = 0; k < 4; k++)
        o[k] = object[i][k];
    mul(modelview, o, e);
    invert(modelview, inv);
    /* n (M^-1), upper 3x3, as a row vector; then normalized (GL_NORMALIZE). */
    for (k = 0; k < 3; k++)
        n[k] = normals[i][0] * inv[k * 4] + normals[i][1] * inv[k * 4 + 1] +
               normals[i][2] * inv[k * 4 + 2];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (k = 0; k < 3; k++)
        n[k] /= len;
    len = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    for (k = 0; k < 3; k++)
        u[k] = e[k] / len;
    nu = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
    for (k = 0; k < 3; k++)
        r[k] = u[k] - 2.0 * n[k] * nu;
    m = 2.0 * sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0) * (r[2] + 1.0));
    if (setting == 0) {
        double ps[4], pq[4];
        for (k = 0; k < 4; k++) {
            ps[k] = object_plane_s[k];
            pq[k] = object_plane_q[k];
        }
        g[0] = dot4(ps, o);
        eye_plane(eye_plane_t, plane_modelview, plane);
        g[1] = dot4(plane, e);
        g[2] = r[2];
        g[3] = dot4(pq, o);
    } else {
        g[0] = r[0] / m + 0.5;
        g[1] = r[1] / m + 0.5;
        g[2] = n[2];
        eye_plane(eye_plane_q, modelview, plane);
        g[3] = dot4(plane, e);
    }
    mul(texture_matrix, g, out);
}

static void note(void *user, GLenum mode, GLenum token, const GLfloat *vertices, int nverts,
                 int k, GLenum type)
{
    double expect[4];
    (void)user; (void)mode; (void)token; (void)vertices; (void)nverts; (void)k; (void)type;
    reference(noted % POINTS, expect);
    noted++;
    printf(" ref");
    ffl_pdv("strq", expect, 4);
}

static void set_modes(void)
{
    if (setting == 0) {
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glTexGenfv(GL_S, GL_OBJECT_PLANE, object_plane_s);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
        glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glTexGenfv(GL_Q, GL_OBJECT_PLANE, object_plane_q);
    } else {
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
        glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        /* Given under the drawing modelview. */
        glTexGenfv(GL_Q, GL_EYE_PLANE, eye_plane_q);
    }
}

static int draw(const char *tag)
{
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    int i, failed;
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_4D_COLOR_TEXTURE);
    ffl_fb_begin(&fb, GL_POINTS);
    for (i = 0; i < POINTS; i++) {
        glNormal3fv(normals[i]);
        glTexCoord4fv(currents[i]);
        glVertex4fv(object[i]);
    }
    glEnd();
    ffl_fb_mark(&fb, GL_POINTS);
    glVertexPointer(4, GL_FLOAT, 0, object);
    glNormalPointer(GL_FLOAT, 0, normals);
    glTexCoordPointer(4, GL_FLOAT, 0, currents);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_POINTS, 0, POINTS);
    noted = 0;
    failed = ffl_fb_finish(&fb, tag, note, NULL);
    printf("%s error %s\n", tag, ffl_error_name(glGetError()));
    return failed;
}

int main(void)
{
    ffl_rng rng;
    int i, k, failed = 0;

    ffl_test_init();
    ffl_rng_seed(&rng, 7);
    for (i = 0; i < POINTS; i++) {
        for (k = 0; k < 3; k++) {
            object[i][k] = ffl_rng_float(&rng, -1.0, 1.0);
            normals[i][k] = ffl_rng_float(&rng, -1.0, 1.0);
            currents[i][k] = ffl_rng_float(&rng, -1.0, 1.0);
        }
        object[i][2] -= 4.0f; /* in front of the eye, inside the volume below */
        object[i][3] = i % 3 == 0 ? 1.25f : 1.0f;
        currents[i][3] = 1.0f;
    }
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-8, 8, -8, 8, -20, 20);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.25f, -0.5f, 0.125f);
    glRotatef(30, 0, 0, 1);
    glScalef(2, 0.5f, 1.5f);
    read_matrix(GL_TEXTURE_MATRIX, texture_matrix);
    glMatrixMode(GL_MODELVIEW);
    /* The eye plane of t is given under this modelview. */
    glLoadIdentity();
    glRotatef(-20, 1, 1, 0);
    glTranslatef(0.5f, 0.0f, -1.0f);
    read_matrix(GL_MODELVIEW_MATRIX, plane_modelview);
    glTexGenfv(GL_T, GL_EYE_PLANE, eye_plane_t);
    glLoadIdentity();
    glTranslatef(0.25f, -0.5f, 1.0f);
    glRotatef(40, 0.3f, 1, 0.2f);
    glScalef(1.5f, 0.75f, 1.25f);
    read_matrix(GL_MODELVIEW_MATRIX, modelview);
    glEnable(GL_NORMALIZE);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    for (setting = 0; setting < 2; setting++) {
        set_modes();
        failed |= draw(setting == 0 ? "linear_reflection" : "sphere_normal_eye");
    }
    {
        double plane[4];
        GLint iv[4];
        GLfloat fv[4];
        eye_plane(eye_plane_t, plane_modelview, plane);
        glGetTexGeniv(GL_T, GL_EYE_PLANE, iv);
        printf("eye_plane_int plane_int");
        for (k = 0; k < 4; k++)
            printf(" %d", (int)iv[k]);
        printf(" ref plane_int");
        for (k = 0; k < 4; k++)
            printf(" %d", (int)floor(plane[k] + 0.5));
        printf("\n");
        glTexGenf(GL_S, GL_OBJECT_PLANE, 3.0f);
        printf("scalar_plane error %s ref error GL_INVALID_ENUM\n", ffl_error_name(glGetError()));
        glGetTexGenfv(GL_S, GL_OBJECT_PLANE, fv);
        printf("scalar_plane_after");
        ffl_pfv("plane", fv, 4);
        printf(" ref");
        ffl_pfv("plane", object_plane_s, 4);
        printf("\n");
    }
    return failed;
}
