/* ffl-test: differential */
/*
 * Randomized meshes through the whole pipeline: each mesh is one to four
 * glBegin/glEnd groups of random modes (all ten) and vertex counts (0 to 14,
 * so incomplete primitives too), every vertex with its own color and normal,
 * under a random lighting state (reference/random_state.h, as in
 * random_lighting.c), a random camera (perspective or orthographic, shapes
 * crossing the view volume, vertices behind the eye), random culling, front
 * face and polygon modes per face, and zero to three user clip planes set
 * under their own modelview. Everything is fed back (GL_3D_COLOR) and
 * compared with OSMesa token for token; the fed-back vertices that are drawn
 * vertices also carry the reference's window coordinates and color.
 *
 * Each mesh is made from its own seed (FIRST_SEED + mesh), so a failing mesh
 * can be replayed alone: ./random_meshes <mesh> [<count>].
 *
 * Kept out, because OSMesa is known to differ from the spec there and this
 * program compares with it: glShadeModel(GL_FLAT) (osmesa_diff_flat_feedback.c),
 * edge flags (osmesa_diff_edge_flags.c), material shininess 0
 * (osmesa_diff_shininess0_attenuation.c, osmesa_diff_zero_pow_zero.c) and
 * vertices with w != 1 (osmesa_diff_vertex_w.c), and two-sided lighting with
 * color material tracking the back face alone
 * (osmesa_diff_back_color_material.c).
 *
 * osmesa-known: line-reset
 * (OSMesa feeds back GL_LINE_TOKEN where the spec resets the stipple.)
 */
#include "ffl_test.h"
#include "reference/random_state.h"
#include "reference/vertex_ref.h"

#define NUM_MESHES 480
#define FIRST_SEED 0x6d657368u
#define STRUCTURE_SEED 0x73747563u
/* Meshes share their discrete lighting and clipping choices in groups (Mesa
 * compiles a vertex program for each; see random_lighting.c). */
#define MESHES_PER_STRUCTURE 8
#define BUF_SIZE 65536

static vref_set vref;

static const GLenum all_modes[10] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP,
                                      GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                      GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
static const GLenum polygon_modes[3] = { GL_FILL, GL_LINE, GL_POINT };
static const char *polygon_mode_names[3] = { "fill", "line", "point" };
static const GLenum cull_modes[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
static const char *cull_names[3] = { "front", "back", "front_and_back" };

typedef struct {
    long meshes, primitives, vertices;
    ffl_token_counts tokens;
} totals;

/* Perspective or orthographic, from the structure stream; values from r. */
static void random_camera(ffl_rng *rs, ffl_rng *r, ref_state *ref, double *distance)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (ffl_rng_chance(rs, 0.6)) {
        double n = ffl_rng_float(r, 0.5, 3), f = n + ffl_rng_float(r, 5, 50);
        double half = n * tan(ffl_rng_float(r, 15, 45) * FFL_PI / 180.0);
        double aspect = ffl_rng_float(r, 0.7, 1.4);
        glFrustum(-half, half * ffl_rng_float(r, 0.6, 1.4), -half * aspect, half * aspect, n, f);
        *distance = n + ffl_rng_float(r, 1, 12);
        printf(" frustum");
    } else {
        double e = ffl_rng_float(r, 3, 10), z = ffl_rng_float(r, 1.5, 10);
        glOrtho(-e, e, -e * ffl_rng_float(r, 0.7, 1.4), e, -z, z);
        *distance = 0.0;
        printf(" ortho");
    }
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(ref);
}

/* The drawing modelview: the camera distance, then random operations
 * (a glLoadMatrix among them becomes a glMultMatrix, so the distance stays). */
static void draw_modelview(ffl_rng *rs, ffl_rng *r, mv_ops *ops)
{
    int i;
    random_ops(rs, r, ops);
    for (i = 0; i < ops->n; i++) {
        mv_op *o = &ops->op[i];
        if (o->kind == OP_LOAD)
            o->kind = OP_MULT;
        /* smaller translations, so that most shapes are at least partly in view */
        if (o->kind == OP_TRANSLATE) {
            o->a[0] *= 0.3f; o->a[1] *= 0.3f; o->a[2] *= 0.3f;
        } else if (o->kind == OP_MULT) {
            o->a[12] *= 0.3f; o->a[13] *= 0.3f; o->a[14] *= 0.3f;
        }
    }
}

static void set_draw_modelview(ref_state *ref, double distance, const mv_ops *ops)
{
    mirror_load_identity(ref);
    mirror_translatef(ref, 0, 0, (float)-distance);
    apply_ops(ops, ref, 1);
}

/* Two-sided lighting with glColorMaterial(GL_BACK, ...) tracking anything but
 * the emission: OSMesa's back color is wrong in green and blue
 * (osmesa_diff_back_color_material.c); track both faces instead. */
static void no_back_only_color_material(ref_state *ref)
{
    if (ref->two_side && ref->color_material && ref->color_material_face == GL_BACK &&
        ref->color_material_mode != GL_EMISSION) {
        mirror_color_material(ref, GL_FRONT_AND_BACK, ref->color_material_mode);
        printf(" (color_material front_and_back)");
    }
}

/* No shininess 0: OSMesa's specular term is wrong there (see the header). */
static void nonzero_shininess(ffl_rng *r, ref_state *ref)
{
    int f;
    for (f = 0; f < 2; f++)
        if (ref->material[f].shininess == 0.0)
            mirror_materialf(ref, f == 0 ? GL_FRONT : GL_BACK, GL_SHININESS,
                             ffl_rng_float(r, 0.5, 128));
}

/* 0 to 3 user clip planes through points near the mesh, under their own
 * modelview (the number from the structure stream). */
static void random_clip_planes(ffl_rng *rs, ffl_rng *r, ref_state *ref)
{
    int i, n = ffl_rng_int(rs, 4);
    mv_ops ops;
    random_ops(rs, r, &ops);
    set_modelview(&ops, ref);
    for (i = 0; i < 6; i++)
        glDisable(GL_CLIP_PLANE0 + i);
    printf(" clip_planes %d", n);
    for (i = 0; i < n; i++) {
        GLdouble eqn[4];
        double p[3], len;
        int k;
        do {
            for (k = 0; k < 3; k++)
                eqn[k] = ffl_rng_float(r, -1, 1);
            len = sqrt(eqn[0] * eqn[0] + eqn[1] * eqn[1] + eqn[2] * eqn[2]);
        } while (len < 0.2);
        for (k = 0; k < 3; k++)
            p[k] = ffl_rng_float(r, -3, 3);
        /* mostly keeping the side toward the origin */
        eqn[3] = -(eqn[0] * p[0] + eqn[1] * p[1] + eqn[2] * p[2]) + ffl_rng_float(r, 0, 3) * len;
        glClipPlane(GL_CLIP_PLANE0 + 2 * i, eqn);
        glEnable(GL_CLIP_PLANE0 + 2 * i);
    }
}

/* Culling, front face and polygon modes: per mesh (no vertex program
 * depends on them). */
static void random_rasterization(ffl_rng *r)
{
    int cull = ffl_rng_chance(r, 0.35), c = ffl_rng_int(r, 3), front = ffl_rng_int(r, 2);
    int fm = ffl_rng_int(r, 3), bm = ffl_rng_chance(r, 0.5) ? fm : ffl_rng_int(r, 3);
    if (cull)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glCullFace(cull_modes[c]);
    glFrontFace(front ? GL_CW : GL_CCW);
    glPolygonMode(GL_FRONT, polygon_modes[fm]);
    glPolygonMode(GL_BACK, polygon_modes[bm]);
    printf(" cull %s front_face %s polygon_mode %s %s", cull ? cull_names[c] : "off",
           front ? "cw" : "ccw", polygon_mode_names[fm], polygon_mode_names[bm]);
}

static int run_mesh(int mesh, totals *t)
{
    static GLfloat buf[BUF_SIZE];
    ffl_rng rng, structure_rng, *r = &rng, *rs = &structure_rng;
    ref_state ref;
    mv_ops ops;
    ffl_fb fb;
    double distance, center[4], origin[4] = { 0, 0, 0, 1 };
    char tag[32];
    int g, groups, failed;

    ffl_rng_seed(r, FIRST_SEED + (uint64_t)mesh);
    ffl_rng_seed(rs, STRUCTURE_SEED + (uint64_t)(mesh / MESHES_PER_STRUCTURE));
    ref_init(&ref);
    glDisable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);

    printf("mesh %d", mesh);
    random_camera(rs, r, &ref, &distance);
    draw_modelview(rs, r, &ops);
    {
        ref_state tmp;
        ref_init(&tmp);
        ref_translatef(&tmp, 0, 0, (float)-distance);
        apply_ops(&ops, &tmp, 0);
        ref_eye_position(&tmp, origin, center);
    }
    random_lighting_state(rs, r, &ref, center);
    nonzero_shininess(r, &ref);
    no_back_only_color_material(&ref);
    random_clip_planes(rs, r, &ref);
    random_rasterization(r);
    printf("\n");

    set_draw_modelview(&ref, distance, &ops);
    sprintf(tag, "m%d", mesh);
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(&ref));
    printf("\n");

    vref_start(&vref, &ref);
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    groups = 1 + ffl_rng_int(r, 4);
    for (g = 0; g < groups; g++) {
        GLenum mode = all_modes[ffl_rng_int(r, 10)];
        int count = ffl_rng_int(r, 15);
        vref_draw_shape(&vref, &fb, r, mode, count, ffl_rng_float(r, -3, 3),
                        ffl_rng_float(r, -3, 3), ffl_rng_float(r, 1, 6), ffl_rng_float(r, 0, 3));
        t->vertices += count;
    }
    failed = ffl_fb_finish(&fb, tag, vref_note, &vref);
    t->meshes++;
    t->primitives += groups;
    t->tokens.points += fb.counts.points;
    t->tokens.lines += fb.counts.lines;
    t->tokens.line_resets += fb.counts.line_resets;
    t->tokens.polygons += fb.counts.polygons;
    t->tokens.polygon_vertices += fb.counts.polygon_vertices;
    return failed;
}

int main(int argc, char **argv)
{
    int first = 0, count = NUM_MESHES, m, failed = 0;
    totals t;
    memset(&t, 0, sizeof t);
    if (argc > 1) {
        first = atoi(argv[1]);
        count = argc > 2 ? atoi(argv[2]) : 1;
    }
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glShadeModel(GL_SMOOTH);
    for (m = first; m < first + count; m++)
        failed |= run_mesh(m, &t);
    /* segments: GL_LINE_TOKEN and GL_LINE_RESET_TOKEN together (their split
     * is a known OSMesa difference, checked token by token above) */
    printf("summary meshes %ld glbegin_groups %ld vertices %ld tokens point %ld segment %ld "
           "polygon %ld polygon_vertices %ld\n",
           t.meshes, t.primitives, t.vertices, t.tokens.points,
           t.tokens.lines + t.tokens.line_resets, t.tokens.polygons, t.tokens.polygon_vertices);
    vref_print_counts(&vref);
    return failed;
}
