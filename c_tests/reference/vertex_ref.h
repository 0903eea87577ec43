/*
 * vertex_ref.h - the reference's view of the vertices a program draws: for
 * each glVertex, its window coordinates (§2.11: modelview, projection,
 * perspective division, viewport and depth range, in double from the
 * matrices GL stored) and its lit colors for both faces (lighting_ref.h).
 *
 * A program draws through vref_vertex3f (a glVertex3f that records the
 * vertex) and prints feedback with vref_note as the vertex note of
 * ffl_print_feedback_prims: every fed-back vertex found at the window
 * position of a drawn vertex (within VREF_MATCH pixels: the vertices no
 * clipping created) gets " ref xyz ... rgba ...", the reference's values for
 * the face that the spec selects (§2.14.1: a polygon's facing is the sign of
 * its window-space area; points and lines use the front colors), and
 * " tol ..." for comparisons with float32 implementations; any other
 * fed-back vertex, made by clipping, gets the mark " clip-made". Where the face
 * cannot be known from the token alone (a point or an outline segment of a
 * polygon in GL_POINT or GL_LINE mode, with two-sided lighting), the program
 * may say which face it drew (`polygon_face`); otherwise no ref is printed.
 * Include after gl_mirror.h.
 */
#ifndef FFL_VERTEX_REF_H
#define FFL_VERTEX_REF_H

#define VREF_MAX_VERTICES 4096
/* A fed-back vertex is a drawn vertex if its window x and y are within
 * VREF_MATCH pixels (|dx| + |dy|) and its depth within VREF_MATCH_Z of the
 * drawn vertex's reference position: drawn vertices land within 1e-5 of it
 * in both builds, while a vertex clipping made near a drawn one (the end of
 * a short clipped segment) must not be taken for it. */
#define VREF_MATCH 3e-5
#define VREF_MATCH_Z 3e-6

typedef struct {
    double window[4]; /* x, y, z window coordinates, w the clip w */
    double color[2][4];
    double tolerance[2];
} vref_vertex;

typedef struct {
    ref_state *ref;
    ref_mat4 projection;
    double viewport[4];
    double depth_range[2];
    int front_ccw;
    /* the face of the points and outlines of polygons drawn now: 0 front,
     * 1 back, -1 unknown (then they get no ref with two-sided lighting) */
    int polygon_face;
    int n;
    vref_vertex v[VREF_MAX_VERTICES];
    long matched, unmatched, clip_made; /* with a ref, face unknown, made by clipping */
} vref_set;

/* Starts recording: reads the projection, viewport, depth range and front
 * face GL stored (call outside glBegin/glEnd, after mirror_read_stored_state
 * so the reference's modelview is GL's). */
static inline void vref_start(vref_set *s, ref_state *ref)
{
    GLfloat f[16];
    GLint iv[4];
    int k;
    s->ref = ref;
    glGetFloatv(GL_PROJECTION_MATRIX, f);
    for (k = 0; k < 16; k++)
        s->projection.m[k] = f[k];
    glGetIntegerv(GL_VIEWPORT, iv);
    for (k = 0; k < 4; k++)
        s->viewport[k] = iv[k];
    glGetFloatv(GL_DEPTH_RANGE, f);
    s->depth_range[0] = f[0];
    s->depth_range[1] = f[1];
    glGetIntegerv(GL_FRONT_FACE, iv);
    s->front_ccw = iv[0] == GL_CCW;
    s->polygon_face = -1;
    s->n = 0;
}

/* glVertex3f, recording the vertex's reference window position and colors
 * (the current normal and color are the reference's: set them through the
 * mirror_* calls). */
static inline void vref_vertex3f(vref_set *s, float x, float y, float z)
{
    double obj[4], eye[4], clip[4], secondary[4];
    vref_vertex *v;
    int face;
    glVertex3f(x, y, z);
    if (s->n >= VREF_MAX_VERTICES)
        return;
    v = &s->v[s->n++];
    obj[0] = x; obj[1] = y; obj[2] = z; obj[3] = 1.0;
    ref_eye_position(s->ref, obj, eye);
    ref_mat_transform4(&s->projection, eye, clip);
    v->window[0] = s->viewport[0] + s->viewport[2] * (clip[0] / clip[3] + 1.0) / 2.0;
    v->window[1] = s->viewport[1] + s->viewport[3] * (clip[1] / clip[3] + 1.0) / 2.0;
    v->window[2] = s->depth_range[0] +
                   (s->depth_range[1] - s->depth_range[0]) * (clip[2] / clip[3] + 1.0) / 2.0;
    v->window[3] = clip[3];
    for (face = 0; face < 2; face++) {
        ref_lit_color(s->ref, obj, face, v->color[face], secondary);
        v->tolerance[face] = 1e-5 + 1e-6 * ref_color_sensitivity(s->ref, obj, face, 1e-6);
    }
}

/* Twice the signed window-space area of a fed-back polygon (x, y at offset 0
 * and 1 of each vertex of `size` values). */
static inline double vref_area(const GLfloat *vertices, int nverts, int size)
{
    double a = 0.0;
    int k;
    for (k = 0; k < nverts; k++) {
        const GLfloat *p = vertices + k * size, *q = vertices + ((k + 1) % nverts) * size;
        a += (double)p[0] * q[1] - (double)q[0] * p[1];
    }
    return a;
}

/* The index of the drawn vertex at the fed-back vertex's window position
 * (see VREF_MATCH; `z` the fed-back depth, or NULL for GL_2D), or -1. */
static inline int vref_index_of(const vref_set *s, const GLfloat *fed, const GLfloat *z)
{
    int i, best = -1;
    double best_d = VREF_MATCH;
    for (i = 0; i < s->n; i++) {
        double d = fabs(fed[0] - s->v[i].window[0]) + fabs(fed[1] - s->v[i].window[1]);
        if (z != NULL && fabs(*z - s->v[i].window[2]) > VREF_MATCH_Z)
            continue;
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

/* The vertex note (ffl_vertex_note) that prints the reference's values for a
 * fed-back vertex at a drawn vertex's position. `user` is the vref_set. */
static inline void vref_note(void *user, GLenum mode, GLenum token, const GLfloat *vertices,
                             int nverts, int k, GLenum type)
{
    vref_set *s = (vref_set *)user;
    int size = ffl_feedback_vertex_size(type);
    const GLfloat *fed = vertices + k * size;
    int best, face = 0;
    if (type == GL_2D || type == GL_3D)
        return; /* no color to check */
    best = vref_index_of(s, fed, fed + 2);
    if (best < 0) {
        /* a vertex made by clipping (its coordinates are compared with the
         * harness's tolerance for such vertices) */
        s->clip_made++;
        printf(" clip-made");
        return;
    }
    /* §2.14.1: the back colors only for back-facing polygons with two-sided
     * lighting; a one-sided back face uses the front colors */
    if (s->ref->lighting && s->ref->two_side && mode != GL_POINTS && !ffl_is_line_mode(mode)) {
        if (token == GL_POLYGON_TOKEN && nverts >= 3) {
            /* front only if a > 0 (CCW) or -a > 0 (CW): zero area is back facing */
            double area = vref_area(vertices, nverts, size);
            face = (s->front_ccw ? area > 0.0 : area < 0.0) ? 0 : 1;
        } else if (s->polygon_face >= 0) {
            face = s->polygon_face;
        } else {
            if (getenv("VREF_DEBUG") != NULL)
                fprintf(stderr, "face unknown: front %.9g %.9g %.9g back %.9g %.9g %.9g\n",
                        s->v[best].color[0][0], s->v[best].color[0][1], s->v[best].color[0][2],
                        s->v[best].color[1][0], s->v[best].color[1][1], s->v[best].color[1][2]);
            s->unmatched++;
            return;
        }
    }
    s->matched++;
    printf(" ref");
    if (type == GL_4D_COLOR_TEXTURE)
        ffl_pdv("xyzw", s->v[best].window, 4);
    else
        ffl_pdv("xyz", s->v[best].window, 3);
    ffl_pdv("rgba", s->v[best].color[face], 4);
    printf(" tol");
    ffl_pf(s->v[best].tolerance[face]);
}

/* A random color (mirrored) and unit-ish normal (mirrored) for the next
 * vertex. */
static inline void vref_random_attributes(vref_set *s, ffl_rng *r)
{
    float n[3];
    mirror_color4f(s->ref, ffl_rng_float(r, 0, 1), ffl_rng_float(r, 0, 1),
                   ffl_rng_float(r, 0, 1), ffl_rng_float(r, 0.2, 1));
    n[0] = ffl_rng_float(r, -0.6, 0.6);
    n[1] = ffl_rng_float(r, -0.6, 0.6);
    n[2] = ffl_rng_float(r, 0.5, 1);
    mirror_normal3f(s->ref, n[0], n[1], n[2]);
}

/* "vertices with_ref <n> made_by_clipping <n> face_unknown <n>" */
static inline void vref_print_counts(const vref_set *s)
{
    printf("vertices with_ref %ld made_by_clipping %ld face_unknown %ld\n", s->matched,
           s->clip_made, s->unmatched);
}

#define VREF_MAX_PRIMITIVE 64

/* One glBegin(mode)/glEnd of `count` vertices shaped by ffl_shape, each with
 * its own random color and normal, marked for the feedback printer. */
static inline void vref_draw_shape(vref_set *s, ffl_fb *fb, ffl_rng *r, GLenum mode, int count,
                                   double cx, double cy, double size, double depth)
{
    float p[VREF_MAX_PRIMITIVE][3];
    int k;
    if (count > VREF_MAX_PRIMITIVE)
        count = VREF_MAX_PRIMITIVE;
    ffl_shape(r, mode, count, cx, cy, size, depth, p);
    ffl_fb_begin(fb, mode);
    for (k = 0; k < count; k++) {
        vref_random_attributes(s, r);
        vref_vertex3f(s, p[k][0], p[k][1], p[k][2]);
    }
    glEnd();
}

/* The lit pass of the primitive programs (prim_*.c): a directional LIGHT0
 * with default colors, a positional LIGHT1 (dim diffuse, specular, linear
 * attenuation), a specular material of shininess 20 on both faces and color
 * material. Lighting itself is left to the caller. */
static inline void vref_standard_lights(ref_state *ref)
{
    mirror_light4f(ref, GL_LIGHT0, GL_POSITION, 1, 2, 3, 0);
    mirror_light4f(ref, GL_LIGHT1, GL_POSITION, -3, 1, 6, 1);
    mirror_light4f(ref, GL_LIGHT1, GL_DIFFUSE, 0.4f, 0.3f, 0.2f, 1);
    mirror_light4f(ref, GL_LIGHT1, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_lightf(ref, GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    mirror_material4f(ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
    mirror_materialf(ref, GL_FRONT_AND_BACK, GL_SHININESS, 20);
    mirror_enable(ref, GL_LIGHT0, 1);
    mirror_enable(ref, GL_LIGHT1, 1);
    mirror_enable(ref, GL_COLOR_MATERIAL, 1);
}

#define VREF_PASS_BUFFER_SIZE 8192

/* One feedback pass (GL_3D_COLOR) named `tag`: prints "<tag> stored_state"
 * and the reference's deviation from the state GL stored, then, with the
 * PRNG seeded with `seed`, draws for each of the `mode_count` modes one
 * random shape (vref_draw_shape, centred, size 9, depth 5) of each count
 * 0..max_count, and prints the feedback with the reference's values.
 * Returns nonzero on a feedback failure. */
static inline int vref_pass_modes(vref_set *s, const char *tag, ref_state *ref,
                                  const GLenum *modes, int mode_count, int max_count,
                                  uint64_t seed)
{
    static GLfloat buf[VREF_PASS_BUFFER_SIZE];
    ffl_fb fb;
    ffl_rng r;
    int m, count;
    ffl_rng_seed(&r, seed);
    ffl_fb_init(&fb);
    printf("%s stored_state", tag);
    mirror_print_deviation(mirror_read_stored_state(ref));
    printf("\n");
    vref_start(s, ref);
    ffl_fb_start(&fb, buf, VREF_PASS_BUFFER_SIZE, GL_3D_COLOR);
    for (m = 0; m < mode_count; m++)
        for (count = 0; count <= max_count; count++)
            vref_draw_shape(s, &fb, &r, modes[m], count, 0, 0, 9, 5);
    return ffl_fb_finish(&fb, tag, vref_note, s);
}

/* The whole main of a primitive program: a 64x64 viewport, glOrtho of
 * +-10 on every axis, the modelview rotated by 25 degrees about
 * (0.3, 0.2, 1), an "unlit" pass, then a "lit" pass with
 * vref_standard_lights, each vref_pass_modes(modes, mode_count, max_count,
 * seed) (the same seed for both), then the vertex counts. Returns the exit
 * status: nonzero if a pass failed. */
static inline int vref_run_primitive_program(const GLenum *modes, int mode_count, int max_count,
                                             uint64_t seed)
{
    static vref_set vref;
    ref_state ref;
    int failed = 0;

    ffl_test_init();
    ref_init(&ref);
    mirror_box_view(&ref, 10);
    mirror_rotatef(&ref, 25, 0.3f, 0.2f, 1);

    failed |= vref_pass_modes(&vref, "unlit", &ref, modes, mode_count, max_count, seed);
    vref_standard_lights(&ref);
    mirror_enable(&ref, GL_LIGHTING, 1);
    failed |= vref_pass_modes(&vref, "lit", &ref, modes, mode_count, max_count, seed);
    vref_print_counts(&vref);
    return failed;
}

#endif /* FFL_VERTEX_REF_H */
