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
#include "reference/random_state.h"

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
    int i;
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
    random_lighting_state(rs, r, &ref, center);
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
