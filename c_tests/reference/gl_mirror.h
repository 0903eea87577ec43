/*
 * gl_mirror.h - GL calls made together with their reference mirror.
 *
 * Each mirror_* function makes one GL call and the matching ref_* call with
 * the same arguments, so the reference keeps the state the program set.
 * mirror_read_stored_state makes the reference take the state GL stored (in
 * single precision) before it evaluates. mirror_draw_points draws vertices
 * as GL_POINTS in feedback mode and prints each fed-back vertex with its
 * reference color.
 * Include after ffl_test.h.
 */
#ifndef FFL_GL_MIRROR_H
#define FFL_GL_MIRROR_H

#include "lighting_ref.h"

static inline void mirror_lightfv(ref_state *ref, GLenum light, GLenum pname, const float *p)
{
    glLightfv(light, pname, p);
    ref_lightfv(ref, light, pname, p);
}

static inline void mirror_lightf(ref_state *ref, GLenum light, GLenum pname, float p)
{
    glLightf(light, pname, p);
    ref_lightf(ref, light, pname, p);
}

static inline void mirror_light4f(ref_state *ref, GLenum light, GLenum pname, float a, float b,
                                  float c, float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    mirror_lightfv(ref, light, pname, p);
}

static inline void mirror_materialfv(ref_state *ref, GLenum face, GLenum pname, const float *p)
{
    glMaterialfv(face, pname, p);
    ref_materialfv(ref, face, pname, p);
}

static inline void mirror_materialf(ref_state *ref, GLenum face, GLenum pname, float p)
{
    glMaterialf(face, pname, p);
    ref_materialf(ref, face, pname, p);
}

static inline void mirror_material4f(ref_state *ref, GLenum face, GLenum pname, float a, float b,
                                     float c, float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    mirror_materialfv(ref, face, pname, p);
}

static inline void mirror_light_model4f(ref_state *ref, GLenum pname, float a, float b, float c,
                                        float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    glLightModelfv(pname, p);
    ref_light_modelfv(ref, pname, p);
}

static inline void mirror_light_modeli(ref_state *ref, GLenum pname, GLint v)
{
    glLightModeli(pname, v);
    ref_light_modeli(ref, pname, v);
}

static inline void mirror_enable(ref_state *ref, GLenum cap, int on)
{
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + REF_MAX_LIGHTS)
        ref->light[cap - GL_LIGHT0].enabled = on;
    else if (cap == GL_LIGHTING)
        ref->lighting = on;
    else if (cap == GL_NORMALIZE)
        ref->normalize = on;
    else if (cap == GL_RESCALE_NORMAL)
        ref->rescale_normal = on;
    else if (cap == GL_COLOR_MATERIAL)
        ref_set_color_material_enabled(ref, on);
}

static inline void mirror_color_material(ref_state *ref, GLenum face, GLenum mode)
{
    glColorMaterial(face, mode);
    ref_color_material(ref, face, mode);
}

static inline void mirror_color4f(ref_state *ref, float r, float g, float b, float a)
{
    glColor4f(r, g, b, a);
    ref_color4f(ref, r, g, b, a);
}

static inline void mirror_normal3f(ref_state *ref, float x, float y, float z)
{
    glNormal3f(x, y, z);
    ref_normal3f(ref, x, y, z);
}

/* Modelview matrix operations (the caller has selected GL_MODELVIEW). */
static inline void mirror_load_identity(ref_state *ref)
{
    glLoadIdentity();
    ref_load_identity(ref);
}

static inline void mirror_translatef(ref_state *ref, float x, float y, float z)
{
    glTranslatef(x, y, z);
    ref_translatef(ref, x, y, z);
}

static inline void mirror_rotatef(ref_state *ref, float a, float x, float y, float z)
{
    glRotatef(a, x, y, z);
    ref_rotatef(ref, a, x, y, z);
}

static inline void mirror_scalef(ref_state *ref, float x, float y, float z)
{
    glScalef(x, y, z);
    ref_scalef(ref, x, y, z);
}

static inline void mirror_mult_matrixf(ref_state *ref, const float *m)
{
    glMultMatrixf(m);
    ref_mult_matrixf(ref, m);
}

/* A 64x64 viewport and the orthographic box of +-half on every axis, with the
 * modelview selected and set to identity (GL and ref). */
static inline void mirror_box_view(ref_state *ref, double half)
{
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-half, half, -half, half, -half, half);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(ref);
}

/* mirror_box_view large enough for every test vertex. */
static inline void mirror_standard_view(ref_state *ref)
{
    mirror_box_view(ref, 100);
}

/* ---- the stored state --------------------------------------------------- */

/* How far a stored value is from the reference's own double-precision copy,
 * relative to the vector's size (at least 1). */
static inline double mirror_deviation(const double *stored, const double *exact, int n)
{
    double scale = 1.0, worst = 0.0;
    int k;
    for (k = 0; k < n; k++)
        if (fabs(exact[k]) > scale)
            scale = fabs(exact[k]);
    for (k = 0; k < n; k++)
        if (fabs(stored[k] - exact[k]) > worst)
            worst = fabs(stored[k] - exact[k]);
    return worst / scale;
}

/* Reads n floats of state into d, returns its deviation from d's old value. */
static inline double mirror_take(double *d, const GLfloat *stored, int n)
{
    double s[16], dev;
    int k;
    for (k = 0; k < n; k++)
        s[k] = stored[k];
    dev = mirror_deviation(s, d, n);
    for (k = 0; k < n; k++)
        d[k] = s[k];
    return dev;
}

/* Whether the current color replaces material property `prop` of face 0
 * (front) or 1 (back) while GL_COLOR_MATERIAL is enabled (§2.14.3). */
static inline int mirror_tracked(const ref_state *ref, int face, GLenum prop)
{
    GLenum f = ref->color_material_face, m = ref->color_material_mode;
    if (!ref->color_material)
        return 0;
    if (f != GL_FRONT_AND_BACK && f != (face == 0 ? GL_FRONT : GL_BACK))
        return 0;
    return m == prop || (m == GL_AMBIENT_AND_DIFFUSE && (prop == GL_AMBIENT || prop == GL_DIFFUSE));
}

/*
 * Makes the reference evaluate the equation on the state as GL stores it.
 *
 * GL keeps its state in single precision: the eye-space light positions and
 * spot directions and the modelview matrix are float results of float
 * arithmetic, while the reference's mirror computed them in double. A high
 * spot exponent or shininess amplifies that difference (up to 1.8e-5 in
 * random_lighting), so before evaluating, the reference reads every piece of
 * lighting state back through GL queries (glGetFloatv, glGetLightfv,
 * glGetMaterialfv, glGetIntegerv, glIsEnabled) and takes those values. It
 * still computes everything else itself, in double, from the specification;
 * it sees the implementation only through GL queries, in each build alike.
 *
 * Returns the largest deviation of a stored value from the mirror's own
 * double-precision state, relative to the size of the vector or matrix it
 * belongs to, over the state that enters the equation (enabled lights, spot
 * parameters of spot lights, material properties not replaced by the current
 * color; not the current color and normal, which programs set per vertex): a
 * program prints it (label `dev`, reference 0) so that a value
 * stored wrongly still fails instead of silently becoming the reference.
 * Call it outside glBegin/glEnd, after the state is set and before drawing;
 * colors given later (glColor with color material) are mirrored as usual.
 */
static inline double mirror_read_stored_state(ref_state *ref)
{
    static const GLenum props[5] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                     GL_SHININESS };
    GLfloat f[16];
    GLint iv[2];
    double dev = 0.0, d;
    int i, face, k;

    /* MIRROR_TAKE(dst, n, counted): dst takes the n stored values in f; their
     * deviation counts if `counted`. */
#define MIRROR_TAKE(dst, n, counted)                                              \
    do {                                                                          \
        d = mirror_take((dst), f, (n));                                           \
        if ((counted) && d > dev)                                                 \
            dev = d;                                                              \
        if ((counted) && d > 1e-6 && getenv("MIRROR_DEBUG") != NULL)              \
            fprintf(stderr, "stored %s (light/face %d) deviates by %g\n", #dst, i, d); \
    } while (0)

    i = -1;
    glGetFloatv(GL_MODELVIEW_MATRIX, f);
    MIRROR_TAKE(ref->modelview.m, 16, 1);

    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        ref_light *l = &ref->light[i];
        GLenum light = GL_LIGHT0 + i;
        int on = glIsEnabled(light) == GL_TRUE, spot;
        l->enabled = on;
        glGetLightfv(light, GL_AMBIENT, f);
        MIRROR_TAKE(l->ambient, 4, on);
        glGetLightfv(light, GL_DIFFUSE, f);
        MIRROR_TAKE(l->diffuse, 4, on);
        glGetLightfv(light, GL_SPECULAR, f);
        MIRROR_TAKE(l->specular, 4, on);
        glGetLightfv(light, GL_POSITION, f);
        MIRROR_TAKE(l->position, 4, on);
        glGetLightfv(light, GL_SPOT_CUTOFF, f);
        spot = f[0] != 180.0f || l->spot_cutoff != 180.0;
        MIRROR_TAKE(&l->spot_cutoff, 1, on);
        glGetLightfv(light, GL_SPOT_DIRECTION, f);
        MIRROR_TAKE(l->spot_direction, 3, on && spot);
        glGetLightfv(light, GL_SPOT_EXPONENT, f);
        MIRROR_TAKE(&l->spot_exponent, 1, on && spot);
        glGetLightfv(light, GL_CONSTANT_ATTENUATION, f);
        MIRROR_TAKE(&l->constant_attenuation, 1, on);
        glGetLightfv(light, GL_LINEAR_ATTENUATION, f);
        MIRROR_TAKE(&l->linear_attenuation, 1, on);
        glGetLightfv(light, GL_QUADRATIC_ATTENUATION, f);
        MIRROR_TAKE(&l->quadratic_attenuation, 1, on);
    }

    i = -1;
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
    MIRROR_TAKE(ref->model_ambient, 4, 1);
    glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, iv);
    ref->local_viewer = iv[0] != 0;
    glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, iv);
    ref->two_side = iv[0] != 0;
    glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, iv);
    ref->separate_specular = iv[0] == GL_SEPARATE_SPECULAR_COLOR;
    glGetIntegerv(GL_COLOR_MATERIAL_FACE, iv);
    ref->color_material_face = (GLenum)iv[0];
    glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, iv);
    ref->color_material_mode = (GLenum)iv[0];
    ref->color_material = glIsEnabled(GL_COLOR_MATERIAL) == GL_TRUE;
    ref->lighting = glIsEnabled(GL_LIGHTING) == GL_TRUE;
    ref->normalize = glIsEnabled(GL_NORMALIZE) == GL_TRUE;
    ref->rescale_normal = glIsEnabled(GL_RESCALE_NORMAL) == GL_TRUE;
    /* programs set the current color and normal before each vertex that
     * needs them, and may start a mirror over without resetting GL's */
    glGetFloatv(GL_CURRENT_COLOR, f);
    MIRROR_TAKE(ref->color, 4, 0);
    glGetFloatv(GL_CURRENT_NORMAL, f);
    MIRROR_TAKE(ref->normal, 3, 0);

    for (face = 0; face < 2; face++) {
        ref_material *m = &ref->material[face];
        double *dst[5];
        i = face;
        dst[0] = m->ambient; dst[1] = m->diffuse; dst[2] = m->specular;
        dst[3] = m->emission; dst[4] = &m->shininess;
        for (k = 0; k < 5; k++) {
            glGetMaterialfv(face == 0 ? GL_FRONT : GL_BACK, props[k], f);
            MIRROR_TAKE(dst[k], k == 4 ? 1 : 4, !mirror_tracked(ref, face, props[k]));
        }
    }
#undef MIRROR_TAKE

    /* the tracked material properties take the current color (§2.14.3) */
    ref_apply_color_material(ref);
    return dev;
}

/* Prints " dev <d> ref dev 0": the stored state's deviation, checked by the
 * harness against 0 with the color tolerance. */
static inline void mirror_print_deviation(double dev)
{
    printf(" dev");
    ffl_pf(dev);
    printf(" ref dev 0");
}

#define MIRROR_MAX_POINTS 64

/* Draws n points in feedback mode (GL_3D_COLOR). First the reference takes
 * the stored state (printed as "<tag> stored_state dev d ref dev 0"). Before
 * vertex k it sets the normal normals[k] and the color colors[k] when those
 * arrays are given. Prints "<tag> <k> xyz x y z rgba r g b a ref rgba r g b a" per vertex,
 * or a line saying what went wrong. Returns 0 on success. */
static inline int mirror_draw_points(ref_state *ref, const char *tag, int n,
                                     const float (*vertices)[3], const float (*normals)[3],
                                     const float (*colors)[4])
{
    GLfloat buf[MIRROR_MAX_POINTS * 8];
    double expect[MIRROR_MAX_POINTS][4], secondary[4];
    GLint count;
    int k;
    if (n > MIRROR_MAX_POINTS)
        n = MIRROR_MAX_POINTS;
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(ref));
    printf("\n");
    glFeedbackBuffer(MIRROR_MAX_POINTS * 8, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    for (k = 0; k < n; k++) {
        double obj[4];
        if (normals != NULL)
            mirror_normal3f(ref, normals[k][0], normals[k][1], normals[k][2]);
        if (colors != NULL)
            mirror_color4f(ref, colors[k][0], colors[k][1], colors[k][2], colors[k][3]);
        glVertex3f(vertices[k][0], vertices[k][1], vertices[k][2]);
        obj[0] = vertices[k][0]; obj[1] = vertices[k][1]; obj[2] = vertices[k][2]; obj[3] = 1.0;
        ref_lit_color(ref, obj, 0, expect[k], secondary);
    }
    glEnd();
    count = glRenderMode(GL_RENDER);
    if (count != n * 8) {
        printf("%s feedback_count %d expected %d\n", tag, (int)count, n * 8);
        return 1;
    }
    for (k = 0; k < n; k++) {
        const GLfloat *fb = buf + k * 8;
        if (fb[0] != (GLfloat)GL_POINT_TOKEN) {
            printf("%s %d not_a_point_token\n", tag, k);
            return 1;
        }
        printf("%s %d", tag, k);
        ffl_pfv("xyz", fb + 1, 3);
        ffl_pfv("rgba", fb + 4, 4);
        printf(" ref");
        ffl_pdv("rgba", expect[k], 4);
        printf("\n");
    }
    return 0;
}

#endif /* FFL_GL_MIRROR_H */
