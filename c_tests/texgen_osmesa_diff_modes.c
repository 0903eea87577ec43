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
 * The reference (reference/texgen_ref.h) reads the matrices back with glGetFloatv (the
 * values GL stored) and evaluates each vertex's generated coordinates in double, then the
 * texture matrix.
 */
#include "ffl_test.h"
#include "reference/texgen_ref.h"

#define POINTS 12
#define BUF_SIZE 4096

static double modelview[16], plane_modelview[16], texture_matrix[16];
static GLfloat object[POINTS][4], normals[POINTS][3], currents[POINTS][4];
static const GLfloat object_plane_s[4] = { 0.5f, -1.25f, 2.0f, 0.25f };
static const GLfloat object_plane_q[4] = { -0.75f, 0.5f, 0.125f, 1.5f };
static const GLfloat eye_plane_t[4] = { 1.5f, 0.25f, -0.5f, 0.75f };
static const GLfloat eye_plane_q[4] = { 0.25f, 1.0f, 0.5f, -0.25f };
static int setting, noted;

/* The spec's texture coordinates of vertex i in the current setting. */
static void reference(int i, double *out)
{
    double o[4], g[4], plane[4];
    tref_vertex v;
    int k;
    for (k = 0; k < 4; k++)
        o[k] = object[i][k];
    tref_vertex_terms(modelview, o, normals[i], &v);
    if (setting == 0) {
        double ps[4], pq[4];
        for (k = 0; k < 4; k++) {
            ps[k] = object_plane_s[k];
            pq[k] = object_plane_q[k];
        }
        g[0] = tref_dot4(ps, o);
        tref_eye_plane(eye_plane_t, plane_modelview, plane);
        g[1] = tref_dot4(plane, v.eye);
        g[2] = v.reflection[2];
        g[3] = tref_dot4(pq, o);
    } else {
        g[0] = v.sphere[0];
        g[1] = v.sphere[1];
        g[2] = v.normal[2];
        tref_eye_plane(eye_plane_q, modelview, plane);
        g[3] = tref_dot4(plane, v.eye);
    }
    tref_mul(texture_matrix, g, out);
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
    tref_read_matrix(GL_TEXTURE_MATRIX, texture_matrix);
    glMatrixMode(GL_MODELVIEW);
    /* The eye plane of t is given under this modelview. */
    glLoadIdentity();
    glRotatef(-20, 1, 1, 0);
    glTranslatef(0.5f, 0.0f, -1.0f);
    tref_read_matrix(GL_MODELVIEW_MATRIX, plane_modelview);
    glTexGenfv(GL_T, GL_EYE_PLANE, eye_plane_t);
    glLoadIdentity();
    glTranslatef(0.25f, -0.5f, 1.0f);
    glRotatef(40, 0.3f, 1, 0.2f);
    glScalef(1.5f, 0.75f, 1.25f);
    tref_read_matrix(GL_MODELVIEW_MATRIX, modelview);
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
        tref_eye_plane(eye_plane_t, plane_modelview, plane);
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
