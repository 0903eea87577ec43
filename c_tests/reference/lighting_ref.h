/*
 * lighting_ref.h - an independent double-precision evaluation of the
 * OpenGL 1.5 lighting equation (§2.14.1), for the C test programs.
 *
 * It keeps its own copy of the state a program sets: the program calls the
 * ref_* mirror of each GL call it makes, with the same float arguments, and
 * this file does the spec's arithmetic in double: its own modelview matrix,
 * the eye-space light positions and spot directions (§2.14.2), the normal
 * transform by the inverse of the upper-left 3x3 (§2.11.3), rescale and
 * normalize, color material tracking (§2.14.3), clamping (§2.14.6).
 *
 * It is written from the specification, not from any implementation; where
 * the specification leaves a choice, the comment says which one is taken.
 * Include it after the GL header (it uses the GL enum names).
 */
#ifndef FFL_LIGHTING_REF_H
#define FFL_LIGHTING_REF_H

#include <math.h>
#include <string.h>

#define REF_MAX_LIGHTS 8

/* 4x4 matrix, column-major like GL: element (row r, column c) is m[c * 4 + r]. */
typedef struct {
    double m[16];
} ref_mat4;

typedef struct {
    int enabled;
    double ambient[4];
    double diffuse[4];
    double specular[4];
    double position[4];       /* eye space, as glLight stored it */
    double spot_direction[3]; /* eye space */
    double spot_exponent;
    double spot_cutoff;
    double constant_attenuation;
    double linear_attenuation;
    double quadratic_attenuation;
} ref_light;

typedef struct {
    double ambient[4];
    double diffuse[4];
    double specular[4];
    double emission[4];
    double shininess;
} ref_material;

typedef struct {
    ref_mat4 modelview; /* the top of the modelview stack */
    ref_light light[REF_MAX_LIGHTS];
    ref_material material[2]; /* 0 = front, 1 = back */
    double model_ambient[4];
    int local_viewer;
    int two_side;
    int separate_specular;
    int lighting;
    int color_material;
    GLenum color_material_face;
    GLenum color_material_mode;
    int normalize;
    int rescale_normal;
    double color[4];  /* current color */
    double normal[3]; /* current normal */
} ref_state;

/* ---- small vector and matrix helpers ----------------------------------- */

static inline void ref_set4(double *d, double a, double b, double c, double e)
{
    d[0] = a; d[1] = b; d[2] = c; d[3] = e;
}

static inline void ref_copy4f(double *d, const float *s)
{
    d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; d[3] = s[3];
}

static inline double ref_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double ref_length3(const double *a)
{
    return sqrt(ref_dot3(a, a));
}

/* Normalizes in place; a zero vector stays zero. */
static inline void ref_normalize3(double *a)
{
    double len = ref_length3(a);
    if (len > 0.0) {
        a[0] /= len; a[1] /= len; a[2] /= len;
    }
}

static inline double ref_clamp01(double v)
{
    return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
}

static inline void ref_mat_identity(ref_mat4 *a)
{
    int i;
    for (i = 0; i < 16; i++)
        a->m[i] = (i % 5 == 0) ? 1.0 : 0.0;
}

/* r = a * b (r may alias neither). */
static inline void ref_mat_mul(ref_mat4 *r, const ref_mat4 *a, const ref_mat4 *b)
{
    int row, col, k;
    for (col = 0; col < 4; col++) {
        for (row = 0; row < 4; row++) {
            double sum = 0.0;
            for (k = 0; k < 4; k++)
                sum += a->m[k * 4 + row] * b->m[col * 4 + k];
            r->m[col * 4 + row] = sum;
        }
    }
}

/* out = a * v for a 4-component column vector. */
static inline void ref_mat_transform4(const ref_mat4 *a, const double *v, double *out)
{
    int row;
    for (row = 0; row < 4; row++)
        out[row] = a->m[row] * v[0] + a->m[4 + row] * v[1] + a->m[8 + row] * v[2] +
                   a->m[12 + row] * v[3];
}

/* out = upper-left 3x3 of a, times v. */
static inline void ref_mat_transform3(const ref_mat4 *a, const double *v, double *out)
{
    int row;
    for (row = 0; row < 3; row++)
        out[row] = a->m[row] * v[0] + a->m[4 + row] * v[1] + a->m[8 + row] * v[2];
}

/* inv = inverse of the upper-left 3x3 of a, as inv[row][col]. Returns 0 if
 * the matrix is singular. */
static inline int ref_mat3_inverse(const ref_mat4 *a, double inv[3][3])
{
    double m[3][3];
    double det;
    int r, c;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++)
            m[r][c] = a->m[c * 4 + r];
    inv[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    inv[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
    inv[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
    inv[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    inv[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
    inv[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
    inv[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    inv[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
    inv[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    det = m[0][0] * inv[0][0] + m[0][1] * inv[1][0] + m[0][2] * inv[2][0];
    if (det == 0.0)
        return 0;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++)
            inv[r][c] /= det;
    return 1;
}

/* ---- state set-up: defaults (§6.2 state tables) ------------------------- */

static inline void ref_init(ref_state *s)
{
    int i;
    memset(s, 0, sizeof *s);
    ref_mat_identity(&s->modelview);
    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        ref_light *l = &s->light[i];
        ref_set4(l->ambient, 0, 0, 0, 1);
        if (i == 0) {
            ref_set4(l->diffuse, 1, 1, 1, 1);
            ref_set4(l->specular, 1, 1, 1, 1);
        } else {
            ref_set4(l->diffuse, 0, 0, 0, 1);
            ref_set4(l->specular, 0, 0, 0, 1);
        }
        ref_set4(l->position, 0, 0, 1, 0);
        l->spot_direction[0] = 0;
        l->spot_direction[1] = 0;
        l->spot_direction[2] = -1;
        l->spot_exponent = 0;
        l->spot_cutoff = 180;
        l->constant_attenuation = 1;
        l->linear_attenuation = 0;
        l->quadratic_attenuation = 0;
    }
    for (i = 0; i < 2; i++) {
        ref_material *m = &s->material[i];
        ref_set4(m->ambient, 0.2, 0.2, 0.2, 1);
        ref_set4(m->diffuse, 0.8, 0.8, 0.8, 1);
        ref_set4(m->specular, 0, 0, 0, 1);
        ref_set4(m->emission, 0, 0, 0, 1);
        m->shininess = 0;
    }
    ref_set4(s->model_ambient, 0.2, 0.2, 0.2, 1);
    s->color_material_face = GL_FRONT_AND_BACK;
    s->color_material_mode = GL_AMBIENT_AND_DIFFUSE;
    ref_set4(s->color, 1, 1, 1, 1);
    s->normal[0] = 0;
    s->normal[1] = 0;
    s->normal[2] = 1;
}

/* ---- matrices (§2.11.2) ------------------------------------------------- */

static inline void ref_mult_matrix(ref_state *s, const ref_mat4 *b)
{
    ref_mat4 r;
    ref_mat_mul(&r, &s->modelview, b);
    s->modelview = r;
}

static inline void ref_load_identity(ref_state *s)
{
    ref_mat_identity(&s->modelview);
}

static inline void ref_load_matrixf(ref_state *s, const float *m)
{
    int i;
    for (i = 0; i < 16; i++)
        s->modelview.m[i] = m[i];
}

static inline void ref_mult_matrixf(ref_state *s, const float *m)
{
    ref_mat4 b;
    int i;
    for (i = 0; i < 16; i++)
        b.m[i] = m[i];
    ref_mult_matrix(s, &b);
}

static inline void ref_translatef(ref_state *s, float x, float y, float z)
{
    ref_mat4 b;
    ref_mat_identity(&b);
    b.m[12] = x; b.m[13] = y; b.m[14] = z;
    ref_mult_matrix(s, &b);
}

static inline void ref_scalef(ref_state *s, float x, float y, float z)
{
    ref_mat4 b;
    ref_mat_identity(&b);
    b.m[0] = x; b.m[5] = y; b.m[10] = z;
    ref_mult_matrix(s, &b);
}

/* Rotation by `angle` degrees about (x, y, z), normalized (§2.11.2):
 * R = u u^T + cos(a) (I - u u^T) + sin(a) S. */
static inline void ref_rotatef(ref_state *s, float angle, float x, float y, float z)
{
    double u[3];
    double a = (double)angle * 3.14159265358979323846 / 180.0;
    double c = cos(a), sn = sin(a);
    double S[3][3];
    ref_mat4 b;
    int r, col;
    u[0] = x; u[1] = y; u[2] = z;
    ref_normalize3(u);
    S[0][0] = 0;     S[0][1] = -u[2]; S[0][2] = u[1];
    S[1][0] = u[2];  S[1][1] = 0;     S[1][2] = -u[0];
    S[2][0] = -u[1]; S[2][1] = u[0];  S[2][2] = 0;
    ref_mat_identity(&b);
    for (r = 0; r < 3; r++)
        for (col = 0; col < 3; col++)
            b.m[col * 4 + r] = u[r] * u[col] + c * ((r == col ? 1.0 : 0.0) - u[r] * u[col]) +
                               sn * S[r][col];
    ref_mult_matrix(s, &b);
}

/* ---- lights, materials, light model (§2.14.2) --------------------------- */

static inline void ref_lightfv(ref_state *s, GLenum light, GLenum pname, const float *p)
{
    ref_light *l = &s->light[light - GL_LIGHT0];
    double v[4];
    switch (pname) {
    case GL_AMBIENT: ref_copy4f(l->ambient, p); break;
    case GL_DIFFUSE: ref_copy4f(l->diffuse, p); break;
    case GL_SPECULAR: ref_copy4f(l->specular, p); break;
    case GL_POSITION:
        /* transformed by the modelview matrix in force now */
        ref_copy4f(v, p);
        ref_mat_transform4(&s->modelview, v, l->position);
        break;
    case GL_SPOT_DIRECTION:
        /* transformed by the upper-left 3x3 of the modelview matrix */
        v[0] = p[0]; v[1] = p[1]; v[2] = p[2];
        ref_mat_transform3(&s->modelview, v, l->spot_direction);
        break;
    case GL_SPOT_EXPONENT: l->spot_exponent = p[0]; break;
    case GL_SPOT_CUTOFF: l->spot_cutoff = p[0]; break;
    case GL_CONSTANT_ATTENUATION: l->constant_attenuation = p[0]; break;
    case GL_LINEAR_ATTENUATION: l->linear_attenuation = p[0]; break;
    case GL_QUADRATIC_ATTENUATION: l->quadratic_attenuation = p[0]; break;
    default: break;
    }
}

static inline void ref_lightf(ref_state *s, GLenum light, GLenum pname, float p)
{
    ref_lightfv(s, light, pname, &p);
}

static inline void ref_material_face(ref_material *m, GLenum pname, const float *p)
{
    switch (pname) {
    case GL_AMBIENT: ref_copy4f(m->ambient, p); break;
    case GL_DIFFUSE: ref_copy4f(m->diffuse, p); break;
    case GL_SPECULAR: ref_copy4f(m->specular, p); break;
    case GL_EMISSION: ref_copy4f(m->emission, p); break;
    case GL_AMBIENT_AND_DIFFUSE:
        ref_copy4f(m->ambient, p);
        ref_copy4f(m->diffuse, p);
        break;
    case GL_SHININESS: m->shininess = p[0]; break;
    default: break;
    }
}

static inline void ref_materialfv(ref_state *s, GLenum face, GLenum pname, const float *p)
{
    if (face == GL_FRONT || face == GL_FRONT_AND_BACK)
        ref_material_face(&s->material[0], pname, p);
    if (face == GL_BACK || face == GL_FRONT_AND_BACK)
        ref_material_face(&s->material[1], pname, p);
}

static inline void ref_materialf(ref_state *s, GLenum face, GLenum pname, float p)
{
    ref_materialfv(s, face, pname, &p);
}

static inline void ref_light_modelfv(ref_state *s, GLenum pname, const float *p)
{
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: ref_copy4f(s->model_ambient, p); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: s->local_viewer = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: s->two_side = p[0] != 0.0f; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        s->separate_specular = (GLenum)p[0] == GL_SEPARATE_SPECULAR_COLOR;
        break;
    default: break;
    }
}

static inline void ref_light_modeli(ref_state *s, GLenum pname, GLint v)
{
    float f = (float)v;
    ref_light_modelfv(s, pname, &f);
}

/* ---- color material (§2.14.3) ------------------------------------------- */

/* Copies the current color into the material properties being tracked. */
static inline void ref_apply_color_material(ref_state *s)
{
    float c[4];
    if (!s->color_material)
        return;
    c[0] = (float)s->color[0]; c[1] = (float)s->color[1];
    c[2] = (float)s->color[2]; c[3] = (float)s->color[3];
    ref_materialfv(s, s->color_material_face, s->color_material_mode, c);
}

static inline void ref_color_material(ref_state *s, GLenum face, GLenum mode)
{
    s->color_material_face = face;
    s->color_material_mode = mode;
    ref_apply_color_material(s);
}

static inline void ref_set_color_material_enabled(ref_state *s, int enabled)
{
    s->color_material = enabled;
    ref_apply_color_material(s);
}

static inline void ref_color4f(ref_state *s, float r, float g, float b, float a)
{
    ref_set4(s->color, r, g, b, a);
    ref_apply_color_material(s);
}

static inline void ref_normal3f(ref_state *s, float x, float y, float z)
{
    s->normal[0] = x; s->normal[1] = y; s->normal[2] = z;
}

/* ---- the equation ------------------------------------------------------- */

/* Eye-space position of an object-space vertex. */
static inline void ref_eye_position(const ref_state *s, const double *obj, double *eye)
{
    ref_mat_transform4(&s->modelview, obj, eye);
}

/* Eye-space normal (§2.11.3): n' = n M_u^-1 (row vector), then the rescale
 * factor 1/sqrt(m31^2 + m32^2 + m33^2) of M^-1 or normalization. Both
 * enabled: normalization wins (it makes any rescale irrelevant). */
static inline void ref_eye_normal(const ref_state *s, double *out)
{
    double inv[3][3];
    int c;
    if (!ref_mat3_inverse(&s->modelview, inv)) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    for (c = 0; c < 3; c++)
        out[c] = s->normal[0] * inv[0][c] + s->normal[1] * inv[1][c] + s->normal[2] * inv[2][c];
    if (s->normalize) {
        ref_normalize3(out);
    } else if (s->rescale_normal) {
        double f = 1.0 / sqrt(inv[2][0] * inv[2][0] + inv[2][1] * inv[2][1] + inv[2][2] * inv[2][2]);
        out[0] *= f; out[1] *= f; out[2] *= f;
    }
}

/* The per-light factors of the equation for one vertex and face. */
typedef struct {
    double n_dot_l;     /* n . VP_pli (not clamped) */
    double n_dot_h;     /* n . h_i (not clamped) */
    double attenuation; /* att_i */
    double spot;        /* spot_i */
} ref_light_terms;

/* Eye-space vertex (divided by w), eye-space normal (negated for the back
 * face) and, for every enabled light, its factors. */
static inline void ref_vertex_terms(const ref_state *s, const double *obj, int face,
                                    double *v3, double *n, ref_light_terms *terms)
{
    double V[4];
    int i, k;

    ref_eye_position(s, obj, V);
    for (k = 0; k < 3; k++)
        v3[k] = V[k] / V[3];
    ref_eye_normal(s, n);
    if (face == 1) {
        n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2];
    }

    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        const ref_light *l = &s->light[i];
        ref_light_terms *t = &terms[i];
        double L[3], E[3], h[3];
        t->attenuation = 1.0;
        t->spot = 1.0;
        t->n_dot_l = 0.0;
        t->n_dot_h = 0.0;
        if (!l->enabled)
            continue;

        /* VP_pli: unit vector from the vertex to the light */
        if (l->position[3] != 0.0) {
            double d;
            for (k = 0; k < 3; k++)
                L[k] = l->position[k] / l->position[3] - v3[k];
            d = ref_length3(L);
            ref_normalize3(L);
            t->attenuation = 1.0 / (l->constant_attenuation + l->linear_attenuation * d +
                                    l->quadratic_attenuation * d * d);
        } else {
            for (k = 0; k < 3; k++)
                L[k] = l->position[k];
            ref_normalize3(L);
        }

        /* spot_i: the spec compares P_pli->V . s_dli with cos(cutoff) by >=;
         * it applies to directional lights too. */
        if (l->spot_cutoff != 180.0) {
            double sd[3], cos_angle;
            for (k = 0; k < 3; k++)
                sd[k] = l->spot_direction[k];
            ref_normalize3(sd);
            cos_angle = -ref_dot3(L, sd);
            if (cos_angle >= cos(l->spot_cutoff * 3.14159265358979323846 / 180.0))
                t->spot = pow(cos_angle, l->spot_exponent);
            else
                t->spot = 0.0;
        }

        /* h_i = VP_pli + VP_e, normalized; VP_e = (0,0,1) for an infinite viewer */
        if (s->local_viewer) {
            for (k = 0; k < 3; k++)
                E[k] = -v3[k];
            ref_normalize3(E);
        } else {
            E[0] = 0; E[1] = 0; E[2] = 1;
        }
        for (k = 0; k < 3; k++)
            h[k] = L[k] + E[k];
        ref_normalize3(h);

        t->n_dot_l = ref_dot3(n, L);
        t->n_dot_h = ref_dot3(n, h);
    }
}

/* Lights the vertex `obj` (object coordinates) with the current normal, for
 * face 0 (front) or 1 (back: the normal is negated and the back material
 * used). `primary` gets the clamped primary color, `secondary` the clamped
 * secondary color (the specular sum with separate specular, zero otherwise;
 * its alpha is left at 0). With lighting disabled the current color passes
 * through, clamped. */
static inline void ref_lit_color(const ref_state *s, const double *obj, int face,
                                 double *primary, double *secondary)
{
    const ref_material *m = &s->material[face];
    ref_light_terms terms[REF_MAX_LIGHTS];
    double v3[3], n[3], c[3], spec_sum[3];
    int i, k;

    if (!s->lighting) {
        for (k = 0; k < 4; k++)
            primary[k] = ref_clamp01(s->color[k]);
        for (k = 0; k < 4; k++)
            secondary[k] = 0.0;
        return;
    }

    ref_vertex_terms(s, obj, face, v3, n, terms);

    /* e_cm + a_cm * a_cs */
    for (k = 0; k < 3; k++) {
        c[k] = m->emission[k] + m->ambient[k] * s->model_ambient[k];
        spec_sum[k] = 0.0;
    }

    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        const ref_light *l = &s->light[i];
        const ref_light_terms *t = &terms[i];
        double n_dot_l = t->n_dot_l > 0.0 ? t->n_dot_l : 0.0;
        double n_dot_h = t->n_dot_h > 0.0 ? t->n_dot_h : 0.0;
        double scale = t->attenuation * t->spot, spec_factor;
        if (!l->enabled)
            continue;
        /* f_i = 1 when n (.) VP_pli != 0, where (.) is the dot product clamped
         * at zero: that is, when n . VP_pli > 0. A shininess of 0 makes the
         * power 1 even where n (.) h_i = 0 (0^0 = 1, the limit as the
         * exponent goes to 0). */
        spec_factor = t->n_dot_l > 0.0 ? pow(n_dot_h, m->shininess) : 0.0;
        for (k = 0; k < 3; k++) {
            double amb = m->ambient[k] * l->ambient[k];
            double dif = n_dot_l * m->diffuse[k] * l->diffuse[k];
            double spe = spec_factor * m->specular[k] * l->specular[k];
            c[k] += scale * (amb + dif);
            if (s->separate_specular)
                spec_sum[k] += scale * spe;
            else
                c[k] += scale * spe;
        }
    }

    for (k = 0; k < 3; k++) {
        primary[k] = ref_clamp01(c[k]);
        secondary[k] = ref_clamp01(spec_sum[k]);
    }
    /* the lit alpha is the material's diffuse alpha */
    primary[3] = ref_clamp01(m->diffuse[3]);
    secondary[3] = 0.0;
}

/* How strongly the lit color amplifies float rounding: a float32
 * implementation computes n . h_i and the spot cosine with a relative error
 * of a few ulps, and raising them to the power `shininess` or
 * `spot_exponent` multiplies that relative error by the exponent. Returns,
 * for the color component most affected, the sum over lights of exponent
 * times term: the color's error is about this sum times the relative error
 * `rel` of the dot products (a non-unit normal can make n . h_i > 1, and a
 * high shininess then makes the specular term large and sensitive). A
 * component that clamps to 0 or 1 even with that error counts as exact. */
static inline double ref_color_sensitivity(const ref_state *s, const double *obj, int face,
                                           double rel)
{
    const ref_material *m = &s->material[face];
    ref_light_terms terms[REF_MAX_LIGHTS];
    double v3[3], n[3], worst = 0.0;
    int i, k;
    if (!s->lighting)
        return 0.0;
    ref_vertex_terms(s, obj, face, v3, n, terms);
    for (k = 0; k < 3; k++) {
        double sum = 0.0, value = m->emission[k] + m->ambient[k] * s->model_ambient[k];
        double primary_spec = 0.0;
        for (i = 0; i < REF_MAX_LIGHTS; i++) {
            const ref_light *l = &s->light[i];
            const ref_light_terms *t = &terms[i];
            double scale = t->attenuation * t->spot, spec = 0.0, rest;
            if (!l->enabled)
                continue;
            if (t->n_dot_l > 0.0)
                spec = scale * pow(t->n_dot_h > 0.0 ? t->n_dot_h : 0.0, m->shininess) *
                       m->specular[k] * l->specular[k];
            rest = scale * (m->ambient[k] * l->ambient[k] +
                            (t->n_dot_l > 0.0 ? t->n_dot_l : 0.0) * m->diffuse[k] * l->diffuse[k]);
            value += rest;
            primary_spec += spec;
            if (!s->separate_specular)
                sum += m->shininess * fabs(spec);
            if (l->spot_cutoff != 180.0)
                sum += l->spot_exponent * fabs(rest + (s->separate_specular ? 0.0 : spec));
        }
        if (!s->separate_specular)
            value += primary_spec;
        if (value - sum * rel > 1.0 || value + sum * rel < 0.0)
            continue; /* clamped either way */
        if (sum > worst)
            worst = sum;
    }
    return worst;
}

#endif /* FFL_LIGHTING_REF_H */
