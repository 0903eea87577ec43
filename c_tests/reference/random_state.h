/*
 * random_state.h - random lighting states and modelviews, set on GL and on
 * the reference at once (shared by random_lighting.c and random_meshes.c).
 *
 * Each generator takes two random streams: `rs` for discrete choices (which
 * lights, their kinds, the enables, the modes, the kinds of matrix
 * operations) and `r` for values. Mesa compiles one vertex program per
 * discrete configuration, so a program can share `rs` between several
 * states to keep the OSMesa run short without narrowing the values tested.
 * Include after ffl_test.h.
 */
#ifndef FFL_RANDOM_STATE_H
#define FFL_RANDOM_STATE_H

#include "gl_mirror.h"

/* one modelview operation, applied identically to GL and to the reference */
enum { OP_TRANSLATE, OP_ROTATE, OP_SCALE, OP_MULT, OP_LOAD };

typedef struct {
    int kind;
    float a[16];
} mv_op;

typedef struct {
    int n;
    mv_op op[4];
} mv_ops;

static inline void apply_ops(const mv_ops *ops, ref_state *ref, int to_gl)
{
    int i;
    for (i = 0; i < ops->n; i++) {
        const mv_op *o = &ops->op[i];
        switch (o->kind) {
        case OP_TRANSLATE:
            if (to_gl) glTranslatef(o->a[0], o->a[1], o->a[2]);
            ref_translatef(ref, o->a[0], o->a[1], o->a[2]);
            break;
        case OP_ROTATE:
            if (to_gl) glRotatef(o->a[0], o->a[1], o->a[2], o->a[3]);
            ref_rotatef(ref, o->a[0], o->a[1], o->a[2], o->a[3]);
            break;
        case OP_SCALE:
            if (to_gl) glScalef(o->a[0], o->a[1], o->a[2]);
            ref_scalef(ref, o->a[0], o->a[1], o->a[2]);
            break;
        case OP_MULT:
            if (to_gl) glMultMatrixf(o->a);
            ref_mult_matrixf(ref, o->a);
            break;
        case OP_LOAD:
            if (to_gl) glLoadMatrixf(o->a);
            ref_load_matrixf(ref, o->a);
            break;
        default:
            break;
        }
    }
}

/* A random affine matrix whose 3x3 part is well conditioned enough that the
 * float inverse an implementation computes stays close to the exact one. */
static inline void random_affine(ffl_rng *r, float *m)
{
    for (;;) {
        ref_mat4 t;
        double inv[3][3], det;
        int i;
        for (i = 0; i < 16; i++)
            m[i] = 0.0f;
        for (i = 0; i < 3; i++) {
            m[i * 4 + 0] = ffl_rng_float(r, -1, 1);
            m[i * 4 + 1] = ffl_rng_float(r, -1, 1);
            m[i * 4 + 2] = ffl_rng_float(r, -1, 1);
            m[i * 4 + i] += 1.5f;
        }
        m[12] = ffl_rng_float(r, -3, 3);
        m[13] = ffl_rng_float(r, -3, 3);
        m[14] = ffl_rng_float(r, -3, 3);
        m[15] = 1.0f;
        for (i = 0; i < 16; i++)
            t.m[i] = m[i];
        if (!ref_mat3_inverse(&t, inv))
            continue;
        det = t.m[0] * (t.m[5] * t.m[10] - t.m[9] * t.m[6]) -
              t.m[4] * (t.m[1] * t.m[10] - t.m[9] * t.m[2]) +
              t.m[8] * (t.m[1] * t.m[6] - t.m[5] * t.m[2]);
        if (fabs(det) > 0.5)
            return;
    }
}

/* 1 to 3 random operations: translations, rotations, non-uniform scales
 * (sometimes mirroring), general affine matrices; sometimes a glLoadMatrix
 * first instead of glLoadIdentity. */
static inline void random_ops(ffl_rng *rs, ffl_rng *r, mv_ops *ops)
{
    int i, n = 1 + ffl_rng_int(rs, 3);
    ops->n = 0;
    if (ffl_rng_chance(rs, 0.15)) {
        mv_op *o = &ops->op[ops->n++];
        o->kind = OP_LOAD;
        random_affine(r, o->a);
    }
    for (i = 0; i < n; i++) {
        mv_op *o = &ops->op[ops->n++];
        o->kind = ffl_rng_int(rs, 4);
        switch (o->kind) {
        case OP_TRANSLATE:
            o->a[0] = ffl_rng_float(r, -4, 4);
            o->a[1] = ffl_rng_float(r, -4, 4);
            o->a[2] = ffl_rng_float(r, -4, 4);
            break;
        case OP_ROTATE:
            o->a[0] = ffl_rng_float(r, -180, 180);
            o->a[1] = ffl_rng_float(r, -1, 1);
            o->a[2] = ffl_rng_float(r, -1, 1);
            o->a[3] = ffl_rng_float(r, -1, 1);
            if (fabs(o->a[1]) + fabs(o->a[2]) + fabs(o->a[3]) < 0.1)
                o->a[3] = 1.0f;
            break;
        case OP_SCALE: {
            int k;
            for (k = 0; k < 3; k++) {
                o->a[k] = ffl_rng_float(r, 0.4, 2.5);
                if (ffl_rng_chance(r, 0.1))
                    o->a[k] = -o->a[k];
            }
            break;
        }
        default:
            random_affine(r, o->a);
            break;
        }
    }
}

/* glLoadIdentity and the operations, on GL and on the reference */
static inline void set_modelview(const mv_ops *ops, ref_state *ref)
{
    glLoadIdentity();
    ref_load_identity(ref);
    apply_ops(ops, ref, 1);
}

static inline void random_color(ffl_rng *r, float *c)
{
    c[0] = ffl_rng_float(r, 0, 1);
    c[1] = ffl_rng_float(r, 0, 1);
    c[2] = ffl_rng_float(r, 0, 1);
    c[3] = ffl_rng_float(r, 0, 1);
}

/* rgb in [0, max], alpha in [0, 1] */
static inline void random_color_scaled(ffl_rng *r, float *c, double max)
{
    c[0] = ffl_rng_float(r, 0, max);
    c[1] = ffl_rng_float(r, 0, max);
    c[2] = ffl_rng_float(r, 0, max);
    c[3] = ffl_rng_float(r, 0, 1);
}

/* Sets one light: kind 0 directional, 1 point, 2 spot (positional or, one
 * time in four, directional). The spot direction is aimed roughly at the
 * eye-space center of the vertex cloud `center`, with noise, so that cones
 * catch some vertices and miss others. */
static const char *random_light(ffl_rng *rs, ffl_rng *r, ref_state *ref, int i,
                                const double *center)
{
    GLenum light = GL_LIGHT0 + i;
    float c[4], pos[4];
    int kind = ffl_rng_int(rs, 3);
    const ref_light *l = &ref->light[i];

    /* dim enough that most sums stay below 1 and clamping is the exception */
    random_color_scaled(r, c, 0.3);
    mirror_lightfv(ref, light, GL_AMBIENT, c);
    random_color_scaled(r, c, 0.7);
    mirror_lightfv(ref, light, GL_DIFFUSE, c);
    random_color_scaled(r, c, 0.7);
    mirror_lightfv(ref, light, GL_SPECULAR, c);

    pos[0] = ffl_rng_float(r, -10, 10);
    pos[1] = ffl_rng_float(r, -10, 10);
    pos[2] = ffl_rng_float(r, -10, 10);
    if (kind == 0 || (kind == 2 && ffl_rng_chance(rs, 0.25))) {
        pos[3] = 0.0f;
    } else {
        switch (ffl_rng_int(r, 3)) {
        case 0: pos[3] = 1.0f; break;
        case 1: pos[3] = ffl_rng_float(r, 0.25, 4); break;
        default: pos[3] = ffl_rng_float(r, -2, -0.5); break;
        }
        pos[0] *= pos[3]; pos[1] *= pos[3]; pos[2] *= pos[3];
    }
    mirror_lightfv(ref, light, GL_POSITION, pos);

    /* attenuation: often the default, otherwise random non-negative terms */
    if (ffl_rng_chance(rs, 0.4)) {
        mirror_lightf(ref, light, GL_CONSTANT_ATTENUATION, 1.0f);
        mirror_lightf(ref, light, GL_LINEAR_ATTENUATION, 0.0f);
        mirror_lightf(ref, light, GL_QUADRATIC_ATTENUATION, 0.0f);
    } else {
        float kc = ffl_rng_chance(r, 0.2) ? 0.0f : ffl_rng_float(r, 0.1, 2);
        float kl = ffl_rng_chance(r, 0.4) ? 0.0f : ffl_rng_float(r, 0, 0.5);
        float kq = ffl_rng_chance(r, 0.5) ? 0.0f : ffl_rng_float(r, 0, 0.05);
        if (kc + kl + kq < 0.05f)
            kc = 0.5f;
        mirror_lightf(ref, light, GL_CONSTANT_ATTENUATION, kc);
        mirror_lightf(ref, light, GL_LINEAR_ATTENUATION, kl);
        mirror_lightf(ref, light, GL_QUADRATIC_ATTENUATION, kq);
    }

    if (kind == 2) {
        double want[3], inv[3][3], obj[3], len;
        float dir[3];
        int k;
        /* eye-space direction from the light to the cloud center */
        for (k = 0; k < 3; k++)
            want[k] = l->position[3] != 0.0 ? center[k] - l->position[k] / l->position[3]
                                            : -l->position[k];
        /* back through the current modelview, so that glLight's transform
         * brings it to `want` */
        ref_mat3_inverse(&ref->modelview, inv);
        for (k = 0; k < 3; k++)
            obj[k] = inv[k][0] * want[0] + inv[k][1] * want[1] + inv[k][2] * want[2];
        len = sqrt(obj[0] * obj[0] + obj[1] * obj[1] + obj[2] * obj[2]);
        for (k = 0; k < 3; k++)
            dir[k] = (float)(obj[k] + len * ffl_rng_float(r, -0.3, 0.3));
        mirror_lightfv(ref, light, GL_SPOT_DIRECTION, dir);
        switch (ffl_rng_int(r, 3)) {
        case 0: mirror_lightf(ref, light, GL_SPOT_EXPONENT, 0.0f); break;
        case 1: mirror_lightf(ref, light, GL_SPOT_EXPONENT, ffl_rng_float(r, 0, 8)); break;
        default: mirror_lightf(ref, light, GL_SPOT_EXPONENT, ffl_rng_float(r, 0, 128)); break;
        }
        if (ffl_rng_chance(r, 0.1))
            mirror_lightf(ref, light, GL_SPOT_CUTOFF, 90.0f);
        else
            mirror_lightf(ref, light, GL_SPOT_CUTOFF, ffl_rng_float(r, 0, 89));
    } else {
        /* a light that stops being a spot light keeps its direction */
        mirror_lightf(ref, light, GL_SPOT_CUTOFF, 180.0f);
    }
    return kind == 0 ? "directional" : kind == 1 ? "point" : "spot";
}

static inline void random_material(ffl_rng *rs, ffl_rng *r, ref_state *ref)
{
    static const GLenum props[4] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION };
    float c[4];
    int f, p;
    /* every property of both faces is set, through a random face enum */
    for (f = 0; f < 2; f++) {
        for (p = 0; p < 4; p++) {
            GLenum face = f == 0 ? GL_FRONT : GL_BACK;
            random_color(r, c);
            if (props[p] == GL_EMISSION) {
                c[0] *= 0.3f; c[1] *= 0.3f; c[2] *= 0.3f;
            }
            mirror_materialfv(ref, face, props[p], c);
            if (f == 0 && ffl_rng_chance(r, 0.15))
                mirror_materialfv(ref, GL_FRONT_AND_BACK, props[p], c);
        }
        if (ffl_rng_chance(r, 0.2)) {
            random_color(r, c);
            mirror_materialfv(ref, f == 0 ? GL_FRONT : GL_BACK, GL_AMBIENT_AND_DIFFUSE, c);
        }
        switch (ffl_rng_int(rs, 5)) {
        case 0: c[0] = 0.0f; break;
        case 1: c[0] = ffl_rng_float(r, 0, 5); break;
        default: c[0] = ffl_rng_float(r, 0, 128); break;
        }
        mirror_materialfv(ref, f == 0 ? GL_FRONT : GL_BACK, GL_SHININESS, c);
    }
}

/* Which known OSMesa-vs-spec difference can show at this vertex, if any.
 * Mesa's vertex program takes "shininess is zero" as a property of the state:
 * front shininess 0 and, with two-sided lighting, back shininess 0 too.
 *  - shininess0: in that state, for a light with distance attenuation or a
 *    spot cone, Mesa raises n.h to the power n.l instead of 0; it shows where
 *    n.l > 0 and the light reaches the vertex.
 *  - zero_pow_zero: front shininess 0 but two-sided lighting with a nonzero
 *    back shininess: Mesa evaluates the power and gets 0^0 = 0 where
 *    n.h <= 0 < n.l; the reference takes 0^0 = 1, the limit of x^s as s goes
 *    to 0 and what Mesa's own shininess-0 path gives.
 * Both only touch the specular term, but the whole color is exempted.
 *  - vertex_w: a vertex given with w != 1 is lit by Mesa at (x, y, z)
 *    instead of (x/w, y/w, z/w); it shows with a positional light or a
 *    local viewer (see osmesa_diff_vertex_w.c). */
static inline const char *osmesa_exemption(const ref_state *ref, const double *obj)
{
    ref_light_terms t[REF_MAX_LIGHTS];
    double v3[3], n[3];
    int i, shininess_zero_state;
    if (!ref->lighting)
        return NULL;
    if (obj[3] != 1.0) {
        int uses_position = ref->local_viewer;
        for (i = 0; i < REF_MAX_LIGHTS; i++)
            if (ref->light[i].enabled && ref->light[i].position[3] != 0.0)
                uses_position = 1;
        if (uses_position)
            return "vertex_w";
    }
    if (ref->material[0].shininess != 0.0)
        return NULL;
    shininess_zero_state = !(ref->two_side && ref->material[1].shininess != 0.0);
    ref_vertex_terms(ref, obj, 0, v3, n, t);
    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        const ref_light *l = &ref->light[i];
        if (!l->enabled || t[i].n_dot_l <= 0.0)
            continue;
        if (shininess_zero_state) {
            int attenuated = l->position[3] != 0.0 &&
                             (l->constant_attenuation != 1.0 || l->linear_attenuation != 0.0 ||
                              l->quadratic_attenuation != 0.0);
            if ((attenuated || l->spot_cutoff != 180.0) && t[i].spot > 0.0)
                return "shininess0";
        } else if (t[i].n_dot_h <= 0.0) {
            return "zero_pow_zero";
        }
    }
    return NULL;
}

/* The color tolerance of a float32 evaluation (OSMesa's) at one vertex: the
 * harness's 1e-5, plus what float32 rounding of the dot products (taken as
 * 1e-6 relative, 8 ulps) becomes once raised to the shininess and spot
 * exponents (see ref_color_sensitivity). The harness applies it only where an
 * OSMesa value is compared; fflight is held to 1e-5 against the reference. */
static inline double color_tolerance(const ref_state *ref, const double *obj)
{
    return 1e-5 + 1e-6 * ref_color_sensitivity(ref, obj, 0, 1e-6);
}

/* A whole random lighting state, set on GL and on the reference: the eight
 * lights (each under its own random modelview; `center` is the eye-space
 * point spot lights aim at), both materials, the light model, color
 * material, GL_NORMALIZE, GL_RESCALE_NORMAL and GL_LIGHTING (on 92% of the
 * time). Discrete choices come from `rs`, values from `r`. Prints a summary
 * of the choices (no newline). Leaves the modelview at the last light's. */
static inline void random_lighting_state(ffl_rng *rs, ffl_rng *r, ref_state *ref,
                                         const double *center)
{
    static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    static const char *face_names[3] = { "front", "back", "front_and_back" };
    static const GLenum cm_modes[5] = { GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR,
                                        GL_AMBIENT_AND_DIFFUSE };
    static const char *cm_mode_names[5] = { "emission", "ambient", "diffuse", "specular",
                                            "ambient_and_diffuse" };
    float c[4];
    int i, k, face, mode;

    /* lights, each under its own random modelview (or the previous one) */
    {
        mv_ops light_ops;
        random_ops(rs, r, &light_ops);
        set_modelview(&light_ops, ref);
        for (i = 0; i < REF_MAX_LIGHTS; i++) {
            const char *kind;
            int on = ffl_rng_chance(rs, 0.5);
            if (ffl_rng_chance(rs, 0.5)) {
                random_ops(rs, r, &light_ops);
                set_modelview(&light_ops, ref);
            }
            kind = random_light(rs, r, ref, i, center);
            mirror_enable(ref, GL_LIGHT0 + i, on);
            printf(" light%d %s", i, on ? kind : "off");
        }
    }

    random_material(rs, r, ref);

    c[0] = ffl_rng_float(r, 0, 0.4);
    c[1] = ffl_rng_float(r, 0, 0.4);
    c[2] = ffl_rng_float(r, 0, 0.4);
    c[3] = 1.0f;
    mirror_light_model4f(ref, GL_LIGHT_MODEL_AMBIENT, c[0], c[1], c[2], c[3]);
    k = ffl_rng_int(rs, 2);
    mirror_light_modeli(ref, GL_LIGHT_MODEL_LOCAL_VIEWER, k);
    printf(" local_viewer %d", k);
    k = ffl_rng_int(rs, 2);
    mirror_light_modeli(ref, GL_LIGHT_MODEL_TWO_SIDE, k);
    printf(" two_side %d", k);
    k = ffl_rng_chance(rs, 0.5) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR;
    mirror_light_modeli(ref, GL_LIGHT_MODEL_COLOR_CONTROL, k);
    printf(" %s", k == GL_SEPARATE_SPECULAR_COLOR ? "separate_specular" : "single_color");

    face = ffl_rng_int(rs, 3);
    mode = ffl_rng_int(rs, 5);
    mirror_color_material(ref, faces[face], cm_modes[mode]);
    k = ffl_rng_chance(rs, 0.5);
    mirror_enable(ref, GL_COLOR_MATERIAL, k);
    printf(" color_material %s %s %s", k ? "on" : "off", face_names[face], cm_mode_names[mode]);

    k = ffl_rng_chance(rs, 0.4);
    mirror_enable(ref, GL_NORMALIZE, k);
    printf(" normalize %d", k);
    k = ffl_rng_chance(rs, 0.4);
    mirror_enable(ref, GL_RESCALE_NORMAL, k);
    printf(" rescale_normal %d", k);
    k = ffl_rng_chance(rs, 0.92);
    mirror_enable(ref, GL_LIGHTING, k);
    printf(" lighting %d", k);
}

#endif /* FFL_RANDOM_STATE_H */
