/* ffl-test: differential */
/*
 * Randomized lighting: many random lighting states, each drawn as GL_POINTS
 * in feedback mode (GL_3D_COLOR), every fed-back vertex printed next to the
 * double-precision reference color (reference/lighting_ref.h).
 *
 * Each state is made from its own seed (FIRST_SEED + state number), so a
 * failing state can be replayed alone: ./random_lighting <state> [<count>].
 *
 * Points are lit with the front material only: two-sided lighting selects the
 * back color for back-facing polygons, and points have no facing. Flat
 * shading has no effect on points either (each point is its own provoking
 * vertex), so the shade model is left alone here.
 *
 * Vertices where OSMesa is known to differ from the spec are marked
 * osmesa-exempt=<reason> and compared with the reference only; see
 * osmesa_exemption() for the cases.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

#include <string.h>

#define NUM_STATES 520
#define VERTICES_PER_STATE 20
#define FIRST_SEED 0x6c696768u
#define STRUCTURE_SEED 0x73747275u
/* Discrete choices (which lights, their kinds, the enables, the modes, the
 * kinds of matrix operations) come from a second generator shared by groups
 * of STATES_PER_STRUCTURE consecutive states; all values differ from state to
 * state. Mesa compiles one vertex program per discrete configuration (a few
 * tens of milliseconds of LLVM each), so sharing them keeps the OSMesa run
 * short without narrowing the values tested. */
#define STATES_PER_STRUCTURE 4
#define ORTHO 1000.0

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

static void apply_ops(const mv_ops *ops, ref_state *ref, int to_gl)
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
static void random_affine(ffl_rng *r, float *m)
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
static void random_ops(ffl_rng *rs, ffl_rng *r, mv_ops *ops)
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
static void set_modelview(const mv_ops *ops, ref_state *ref)
{
    glLoadIdentity();
    ref_load_identity(ref);
    apply_ops(ops, ref, 1);
}

static void random_color(ffl_rng *r, float *c)
{
    c[0] = ffl_rng_float(r, 0, 1);
    c[1] = ffl_rng_float(r, 0, 1);
    c[2] = ffl_rng_float(r, 0, 1);
    c[3] = ffl_rng_float(r, 0, 1);
}

/* rgb in [0, max], alpha in [0, 1] */
static void random_color_scaled(ffl_rng *r, float *c, double max)
{
    c[0] = ffl_rng_float(r, 0, max);
    c[1] = ffl_rng_float(r, 0, max);
    c[2] = ffl_rng_float(r, 0, max);
    c[3] = ffl_rng_float(r, 0, 1);
}

static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
static const char *face_names[3] = { "front", "back", "front_and_back" };
static const GLenum cm_modes[5] = { GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR,
                                    GL_AMBIENT_AND_DIFFUSE };
static const char *cm_mode_names[5] = { "emission", "ambient", "diffuse", "specular",
                                        "ambient_and_diffuse" };

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

static void random_material(ffl_rng *rs, ffl_rng *r, ref_state *ref)
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
static const char *osmesa_exemption(const ref_state *ref, const double *obj)
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
static double color_tolerance(const ref_state *ref, const double *obj)
{
    return 1e-5 + 1e-6 * ref_color_sensitivity(ref, obj, 0, 1e-6);
}

/* A random object-space vertex, kept away from positional lights and, for a
 * local viewer, from the eye (where the lighting vectors are undefined). */
static void random_vertex(ffl_rng *r, const ref_state *ref, float *v)
{
    for (;;) {
        double obj[4], eye[4];
        int i, ok = 1;
        v[0] = ffl_rng_float(r, -4, 4);
        v[1] = ffl_rng_float(r, -4, 4);
        v[2] = ffl_rng_float(r, -4, 4);
        obj[0] = v[0]; obj[1] = v[1]; obj[2] = v[2]; obj[3] = 1.0;
        ref_eye_position(ref, obj, eye);
        if (sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]) < 0.5)
            ok = 0;
        for (i = 0; i < REF_MAX_LIGHTS; i++) {
            const ref_light *l = &ref->light[i];
            double d[3];
            int k;
            if (!l->enabled || l->position[3] == 0.0)
                continue;
            for (k = 0; k < 3; k++)
                d[k] = eye[k] - l->position[k] / l->position[3];
            if (sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) < 0.5)
                ok = 0;
        }
        if (ok)
            return;
    }
}

#ifdef RL_DEBUG
/* gcc -DRL_DEBUG: dump the reference state of each state to stderr */
static void dump_ref(const ref_state *s)
{
    int i, f;
    fprintf(stderr, "modelview");
    for (i = 0; i < 16; i++)
        fprintf(stderr, " %g", s->modelview.m[i]);
    fprintf(stderr, "\nlighting %d local_viewer %d two_side %d separate %d cm %d face %x mode %x "
            "normalize %d rescale %d\n", s->lighting, s->local_viewer, s->two_side,
            s->separate_specular, s->color_material, s->color_material_face,
            s->color_material_mode, s->normalize, s->rescale_normal);
    for (i = 0; i < REF_MAX_LIGHTS; i++) {
        const ref_light *l = &s->light[i];
        if (!l->enabled)
            continue;
        fprintf(stderr, "light%d amb %g %g %g dif %g %g %g spe %g %g %g pos %g %g %g %g "
                "dir %g %g %g exp %g cut %g att %g %g %g\n", i, l->ambient[0], l->ambient[1],
                l->ambient[2], l->diffuse[0], l->diffuse[1], l->diffuse[2], l->specular[0],
                l->specular[1], l->specular[2], l->position[0], l->position[1], l->position[2],
                l->position[3], l->spot_direction[0], l->spot_direction[1],
                l->spot_direction[2], l->spot_exponent, l->spot_cutoff,
                l->constant_attenuation, l->linear_attenuation, l->quadratic_attenuation);
    }
    for (f = 0; f < 2; f++) {
        const ref_material *m = &s->material[f];
        fprintf(stderr, "material%d amb %g %g %g %g dif %g %g %g %g spe %g %g %g emi %g %g %g "
                "shin %g\n", f, m->ambient[0], m->ambient[1], m->ambient[2], m->ambient[3],
                m->diffuse[0], m->diffuse[1], m->diffuse[2], m->diffuse[3], m->specular[0],
                m->specular[1], m->specular[2], m->emission[0], m->emission[1],
                m->emission[2], m->shininess);
    }
}
#endif

static int run_state(int state, long *vertices, long *exempt_shininess0,
                     long *exempt_zero_pow_zero, long *exempt_vertex_w)
{
    ffl_rng rng, structure_rng, *r = &rng, *rs = &structure_rng;
    ref_state ref;
    mv_ops draw_ops;
    double center[4], origin[4] = { 0, 0, 0, 1 };
    GLfloat buf[VERTICES_PER_STATE * 8 + 8];
    float c[4];
    int i, k, face, mode;
    GLint n;

    ffl_rng_seed(r, FIRST_SEED + (uint64_t)state);
    ffl_rng_seed(rs, STRUCTURE_SEED + (uint64_t)(state / STATES_PER_STRUCTURE));
    ref_init(&ref);

    /* Back to defaults where a previous state may have left something: color
     * material first, so that glMaterial is not ignored below. */
    glDisable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-ORTHO, ORTHO, -ORTHO, ORTHO, -ORTHO, ORTHO);
    glMatrixMode(GL_MODELVIEW);

    /* the drawing modelview is chosen first so spot lights can aim at it */
    random_ops(rs, r, &draw_ops);
    {
        ref_state tmp;
        ref_init(&tmp);
        apply_ops(&draw_ops, &tmp, 0);
        ref_eye_position(&tmp, origin, center);
    }

    printf("state %d", state);
    /* lights, each under its own random modelview (or the previous one) */
    {
        mv_ops light_ops;
        random_ops(rs, r, &light_ops);
        set_modelview(&light_ops, &ref);
        for (i = 0; i < REF_MAX_LIGHTS; i++) {
            const char *kind;
            int on = ffl_rng_chance(rs, 0.5);
            if (ffl_rng_chance(rs, 0.5)) {
                random_ops(rs, r, &light_ops);
                set_modelview(&light_ops, &ref);
            }
            kind = random_light(rs, r, &ref, i, center);
            mirror_enable(&ref, GL_LIGHT0 + i, on);
            printf(" light%d %s", i, on ? kind : "off");
        }
    }

    random_material(rs, r, &ref);

    c[0] = ffl_rng_float(r, 0, 0.4);
    c[1] = ffl_rng_float(r, 0, 0.4);
    c[2] = ffl_rng_float(r, 0, 0.4);
    c[3] = 1.0f;
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, c[0], c[1], c[2], c[3]);
    k = ffl_rng_int(rs, 2);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, k);
    printf(" local_viewer %d", k);
    k = ffl_rng_int(rs, 2);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, k);
    printf(" two_side %d", k);
    k = ffl_rng_chance(rs, 0.5) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR;
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_COLOR_CONTROL, k);
    printf(" %s", k == GL_SEPARATE_SPECULAR_COLOR ? "separate_specular" : "single_color");

    face = ffl_rng_int(rs, 3);
    mode = ffl_rng_int(rs, 5);
    mirror_color_material(&ref, faces[face], cm_modes[mode]);
    k = ffl_rng_chance(rs, 0.5);
    mirror_enable(&ref, GL_COLOR_MATERIAL, k);
    printf(" color_material %s %s %s", k ? "on" : "off", face_names[face], cm_mode_names[mode]);

    k = ffl_rng_chance(rs, 0.4);
    mirror_enable(&ref, GL_NORMALIZE, k);
    printf(" normalize %d", k);
    k = ffl_rng_chance(rs, 0.4);
    mirror_enable(&ref, GL_RESCALE_NORMAL, k);
    printf(" rescale_normal %d", k);
    k = ffl_rng_chance(rs, 0.92);
    mirror_enable(&ref, GL_LIGHTING, k);
    printf(" lighting %d", k);
    printf("\n");

    set_modelview(&draw_ops, &ref);
    /* the reference evaluates on the state as GL stored it */
    printf("stored_state %d", state);
    mirror_print_deviation(mirror_read_stored_state(&ref));
    printf("\n");
#ifdef RL_DEBUG
    dump_ref(&ref);
#endif

    /* draw, remembering the reference color of every vertex */
    {
        double ref_color[VERTICES_PER_STATE][4], secondary[4];
        const char *exempt[VERTICES_PER_STATE];
        double tolerance[VERTICES_PER_STATE];
        glFeedbackBuffer((GLsizei)(sizeof buf / sizeof buf[0]), GL_3D_COLOR, buf);
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        for (i = 0; i < VERTICES_PER_STATE; i++) {
            float v[3];
            double obj[4];
            if (i == 0 || ffl_rng_chance(r, 0.7)) {
                random_color(r, c);
                mirror_color4f(&ref, c[0], c[1], c[2], c[3]);
            }
            if (i == 0 || ffl_rng_chance(r, 0.8)) {
                float nv[3];
                double len;
                do {
                    nv[0] = ffl_rng_float(r, -1, 1);
                    nv[1] = ffl_rng_float(r, -1, 1);
                    nv[2] = ffl_rng_float(r, -1, 1);
                    len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
                } while (len < 0.2);
                if (ffl_rng_chance(r, 0.5)) {
                    nv[0] = (float)(nv[0] / len);
                    nv[1] = (float)(nv[1] / len);
                    nv[2] = (float)(nv[2] / len);
                }
                mirror_normal3f(&ref, nv[0], nv[1], nv[2]);
            }
            random_vertex(r, &ref, v);
            if (ffl_rng_chance(r, 0.08)) {
                /* the same point, given with w != 1 */
                float w = ffl_rng_float(r, 0.5, 2), vw[4];
                vw[0] = v[0] * w; vw[1] = v[1] * w; vw[2] = v[2] * w; vw[3] = w;
                glVertex4fv(vw);
                obj[0] = vw[0]; obj[1] = vw[1]; obj[2] = vw[2]; obj[3] = vw[3];
            } else {
                glVertex3f(v[0], v[1], v[2]);
                obj[0] = v[0]; obj[1] = v[1]; obj[2] = v[2]; obj[3] = 1.0;
            }
            ref_lit_color(&ref, obj, 0, ref_color[i], secondary);
            exempt[i] = osmesa_exemption(&ref, obj);
            tolerance[i] = color_tolerance(&ref, obj);
#ifdef RL_DEBUG
            {
                ref_light_terms t[REF_MAX_LIGHTS];
                double v3[3], nn[3];
                int l;
                ref_vertex_terms(&ref, obj, 0, v3, nn, t);
                fprintf(stderr, "vertex %d eye %g %g %g n %g %g %g |n| %g\n", i, v3[0], v3[1],
                        v3[2], nn[0], nn[1], nn[2], sqrt(ref_dot3(nn, nn)));
                for (l = 0; l < REF_MAX_LIGHTS; l++)
                    if (ref.light[l].enabled)
                        fprintf(stderr, "  light%d n.l %.9g n.h %.9g att %.9g spot %.9g\n", l,
                                t[l].n_dot_l, t[l].n_dot_h, t[l].attenuation, t[l].spot);
            }
#endif
        }
        glEnd();
        n = glRenderMode(GL_RENDER);

        if (n != VERTICES_PER_STATE * 8) {
            printf("state %d feedback_count %d\n", state, (int)n);
            return 1;
        }
        for (i = 0; i < VERTICES_PER_STATE; i++) {
            const GLfloat *fb = buf + i * 8;
            if (fb[0] != (GLfloat)GL_POINT_TOKEN) {
                printf("state %d vertex %d not_a_point_token\n", state, i);
                return 1;
            }
            printf("v %d %d", state, i);
            if (exempt[i] != NULL) {
                printf(" osmesa-exempt=%s", exempt[i]);
                if (exempt[i][0] == 's')
                    ++*exempt_shininess0;
                else if (exempt[i][0] == 'z')
                    ++*exempt_zero_pow_zero;
                else
                    ++*exempt_vertex_w;
            }
            ffl_pfv("xyz", fb + 1, 3);
            ffl_pfv("rgba", fb + 4, 4);
            printf(" ref");
            ffl_pdv("rgba", ref_color[i], 4);
            printf(" tol");
            ffl_pf(tolerance[i]);
            printf("\n");
        }
    }
    *vertices += VERTICES_PER_STATE;
    return 0;
}

int main(int argc, char **argv)
{
    int first = 0, count = NUM_STATES, s, failed = 0;
    long vertices = 0, shininess0 = 0, zero_pow_zero = 0, vertex_w = 0;
    if (argc > 1) {
        first = atoi(argv[1]);
        count = argc > 2 ? atoi(argv[2]) : 1;
    }
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    for (s = first; s < first + count; s++)
        failed |= run_state(s, &vertices, &shininess0, &zero_pow_zero, &vertex_w);
    printf("summary states %d vertices %ld osmesa_exempt shininess0 %ld zero_pow_zero %ld "
           "vertex_w %ld\n",
           count, vertices, shininess0, zero_pow_zero, vertex_w);
    return failed;
}
