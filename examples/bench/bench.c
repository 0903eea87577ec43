/* `make bench`: lit vertices through fflight and through OSMesa (-DUSE_OSMESA), one source
 * built twice so both run the same scenes on the same data.
 *
 *   bench SCENE|all [VERTICES [RUNS]]
 *
 * A timed scene runs once to warm up (OSMesa compiles its vertex program then) and RUNS more
 * times (default 5), and prints one line, `scene key=value ...`, with the median in
 * ns_per_vertex. A memory scene (fflight only, not part of "all": its peak must not mix
 * with another scene's) prints the growth of the peak resident set over one large call.
 * Any error or unexpected feedback count exits 1. */
#define _POSIX_C_SOURCE 199309L
#include <GL/gl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef USE_OSMESA
#include <GL/osmesa.h>
#else
#include "fflight.h"
#endif

#define BATCH 4096 /* vertices per glBegin/glEnd in immediate mode */
#define WARMUP 1000 /* vertices of the call that brings a memory scene to its baseline */

static GLfloat *positions, *normals;
static GLfloat *out_a; /* the feedback buffer, or fflLightVertices' clip positions */
static GLfloat *out_b; /* fflLightVertices' front colors */
static GLuint *indices;
static GLint vertices, triangles;

static void fail(const char *what)
{
    fprintf(stderr, "bench: %s\n", what);
    exit(1);
}

static void *allocate(size_t floats)
{
    void *p = malloc(floats * sizeof(GLfloat));
    if (!p)
        fail("out of memory");
    /* Touch it, so its pages count before timing (not with zeros: the compiler would turn
     * malloc + memset 0 into a calloc that touches nothing). */
    memset(p, 0x3f, floats * sizeof(GLfloat));
    return p;
}

/* Our own generator, so both builds see the same data whatever the C library; every scene
 * starts from the same seed, whatever ran before it. */
static uint32_t lcg_state;

static float lcg(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return (float)(lcg_state >> 8) * (1.0f / 16777216.0f);
}

/* A normal of length 0.5 to 2, so that GL_NORMALIZE has work to do. */
static void set_normal(GLfloat *n, float x, float y, float z)
{
    float scale = (0.5f + 1.5f * lcg()) / sqrtf(x * x + y * y + z * z);
    n[0] = x * scale, n[1] = y * scale, n[2] = z * scale;
}

/* Random points in the object-space box |x|, |y| <= 0.7, |z| <= 1: inside the view volume
 * under the scene's transform (see setup). */
static void fill_points(GLint n)
{
    GLint i;
    lcg_state = 12345u;
    vertices = n;
    positions = allocate(3 * (size_t)n);
    normals = allocate(3 * (size_t)n);
    for (i = 0; i < n; i++) {
        GLfloat *p = positions + 3 * i, x, y, z;
        p[0] = 1.4f * lcg() - 0.7f, p[1] = 1.4f * lcg() - 0.7f, p[2] = 2.0f * lcg() - 1.0f;
        do
            x = 2.0f * lcg() - 1.0f, y = 2.0f * lcg() - 1.0f, z = 2.0f * lcg() - 1.0f;
        while (x * x + y * y + z * z < 0.01f);
        set_normal(normals + 3 * i, x, y, z);
    }
}

/* A side x side height field (side = sqrt(n)), two triangles per cell, so that an interior
 * vertex is shared by six triangles. */
static void fill_grid(GLint n)
{
    GLint side = (GLint)(sqrt((double)n) + 0.5), i, j;
    GLuint *t;
    lcg_state = 12345u;
    if (side < 2)
        fail("a mesh needs at least 4 vertices");
    vertices = side * side;
    triangles = 2 * (side - 1) * (side - 1);
    positions = allocate(3 * (size_t)vertices);
    normals = allocate(3 * (size_t)vertices);
    indices = malloc(3 * (size_t)triangles * sizeof *indices);
    if (!indices)
        fail("out of memory");
    for (j = 0; j < side; j++)
        for (i = 0; i < side; i++) {
            GLfloat *p = positions + 3 * (j * side + i);
            float x = 1.4f * (float)i / (float)(side - 1) - 0.7f;
            float y = 1.4f * (float)j / (float)(side - 1) - 0.7f;
            p[0] = x, p[1] = y, p[2] = 0.3f * sinf(5.0f * x) * cosf(4.0f * y);
            set_normal(normals + 3 * (j * side + i), -1.5f * cosf(5.0f * x) * cosf(4.0f * y),
                       1.2f * sinf(5.0f * x) * sinf(4.0f * y), 1.0f);
        }
    t = indices;
    for (j = 0; j + 1 < side; j++)
        for (i = 0; i + 1 < side; i++) {
            GLuint a = (GLuint)(j * side + i), b = a + 1, c = a + (GLuint)side, d = c + 1;
            *t++ = a, *t++ = b, *t++ = c;
            *t++ = b, *t++ = d, *t++ = c;
        }
}

/* lights == 0: "1 light", GL_LIGHT0 directional, infinite viewer, one-sided, no normalize.
 * lights == k: the first k of 8 attenuated spot lights, local viewer, two-sided, normalize.
 * away: the projection sees none of the points, so OSMesa lights them and draws nothing. */
static void setup(int lights, int away)
{
    static const GLfloat specular[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    static const GLfloat sun[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    int i;

    glViewport(0, 0, 256, 256);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (away)
        glOrtho(9.0, 11.0, 9.0, 11.0, 1.0, 10.0);
    else
        glOrtho(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity(); /* lights are placed in eye coordinates */

    glEnable(GL_LIGHTING);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32.0f);
    for (i = 0; i < 8; i++)
        glDisable(GL_LIGHT0 + i);
    if (lights == 0) {
        glEnable(GL_LIGHT0);
        glLightfv(GL_LIGHT0, GL_POSITION, sun);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
        glDisable(GL_NORMALIZE);
    } else {
        for (i = 0; i < lights; i++) {
            /* On a circle 2 above the scene's center (0, 0, -5), aimed at it. */
            float a = 0.785398f * (float)i, x = 1.5f * cosf(a), y = 1.5f * sinf(a);
            GLfloat position[4] = {x, y, -3.0f, 1.0f}, direction[3] = {-x, -y, -2.0f};
            GLfloat diffuse[4] = {0.3f + 0.08f * (float)i, 0.6f, 0.9f - 0.08f * (float)i, 1.0f};
            GLenum light = GL_LIGHT0 + (GLenum)i;
            glEnable(light);
            glLightfv(light, GL_POSITION, position);
            glLightfv(light, GL_SPOT_DIRECTION, direction);
            glLightf(light, GL_SPOT_CUTOFF, 45.0f + 3.0f * (float)i);
            glLightf(light, GL_SPOT_EXPONENT, 2.0f + 2.0f * (float)i);
            glLightf(light, GL_LINEAR_ATTENUATION, 0.1f + 0.02f * (float)i);
            glLightf(light, GL_QUADRATIC_ATTENUATION, 0.05f + 0.01f * (float)i);
            glLightfv(light, GL_DIFFUSE, diffuse);
            glLightfv(light, GL_SPECULAR, diffuse);
        }
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        glEnable(GL_NORMALIZE);
    }
    /* The scene: centered 5 in front of the eye, turned so the normal matrix is no identity. */
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);

    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
}

static void expect_feedback(GLint values)
{
    GLint count = glRenderMode(GL_RENDER);
    if (count != values) {
        fprintf(stderr, "bench: %d feedback values, expected %d\n", count, values);
        exit(1);
    }
}

/* GL_3D_COLOR: a point is GL_POINT_TOKEN x y z r g b a. */
static void draw_arrays_n(GLint n)
{
    glFeedbackBuffer(8 * n, GL_3D_COLOR, out_a);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_POINTS, 0, n);
    expect_feedback(8 * n);
}

static void draw_arrays(void)
{
    draw_arrays_n(vertices);
}

static void draw_immediate(void)
{
    GLint i = 0;
    glFeedbackBuffer(8 * vertices, GL_3D_COLOR, out_a);
    glRenderMode(GL_FEEDBACK);
    while (i < vertices) {
        GLint end = i + BATCH < vertices ? i + BATCH : vertices;
        glBegin(GL_POINTS);
        for (; i < end; i++) {
            glNormal3fv(normals + 3 * i);
            glVertex3fv(positions + 3 * i);
        }
        glEnd();
    }
    expect_feedback(8 * vertices);
}

/* A triangle is GL_POLYGON_TOKEN 3 and three vertices of 7 values; none is clipped. */
static void draw_mesh(void)
{
    glFeedbackBuffer(23 * triangles + 64, GL_3D_COLOR, out_a);
    glRenderMode(GL_FEEDBACK);
    glDrawElements(GL_TRIANGLES, 3 * triangles, GL_UNSIGNED_INT, indices);
    expect_feedback(23 * triangles);
}

#ifdef USE_OSMESA
/* OSMesa's vertex processing alone: the points lie outside the view volume (setup's away). */
static void light_bulk_n(GLint n)
{
    glDrawArrays(GL_POINTS, 0, n);
    glFinish();
}
#else
static void light_bulk_n(GLint n)
{
    fflLightVertices(n, 3, positions, 0, normals, 0, NULL, 0, NULL, 0, out_a, 0, out_b, 0,
                     NULL, 0, NULL, 0, NULL, 0);
}
#endif

static void light_bulk(void)
{
    light_bulk_n(vertices);
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static const struct scene {
    const char *name;
    int lights, away;
    int threads; /* fflight's fflSetThreads: 0 the default (all cores), 1 one thread */
    void (*fill)(GLint n);
    void (*draw)(void);
} scenes[] = {
    {"arrays_1light", 0, 0, 0, fill_points, draw_arrays},
    {"arrays_8spot", 8, 0, 0, fill_points, draw_arrays},
    {"immediate_1light", 0, 0, 0, fill_points, draw_immediate},
    {"immediate_8spot", 8, 0, 0, fill_points, draw_immediate},
    {"mesh_8light", 8, 0, 0, fill_grid, draw_mesh},
    /* OSMesa runs the same draw for both; the driver compares each to fflight's. */
    {"bulk_8spot_1thread", 8, 1, 1, fill_points, light_bulk},
    {"bulk_8spot_threads", 8, 1, 0, fill_points, light_bulk},
    {"lights_1", 1, 0, 0, fill_points, draw_arrays},
    {"lights_2", 2, 0, 0, fill_points, draw_arrays},
    {"lights_3", 3, 0, 0, fill_points, draw_arrays},
    {"lights_4", 4, 0, 0, fill_points, draw_arrays},
    {"lights_5", 5, 0, 0, fill_points, draw_arrays},
    {"lights_6", 6, 0, 0, fill_points, draw_arrays},
    {"lights_7", 7, 0, 0, fill_points, draw_arrays},
    {"lights_8", 8, 0, 0, fill_points, draw_arrays},
};

static void release(void)
{
    free(positions), free(normals), free(out_a), free(out_b), free(indices);
    positions = normals = out_a = out_b = NULL, indices = NULL;
}

static void run_scene(const struct scene *s, GLint n, int runs)
{
    double seconds[64];
    int r;
    if (runs < 1 || runs > 64)
        fail("RUNS must be 1 to 64");
    s->fill(n);
    if (s->draw == light_bulk) /* clip positions and front colors */
        out_a = allocate(4 * (size_t)vertices), out_b = allocate(4 * (size_t)vertices);
    else /* the feedback buffer */
        out_a = allocate(s->draw == draw_mesh ? 23 * (size_t)triangles + 64 : 8 * (size_t)vertices);
    setup(s->lights, s->away);
#ifndef USE_OSMESA
    fflSetThreads(s->threads);
#endif
    s->draw(); /* warm-up */
    for (r = 0; r < runs; r++) {
        double start = now();
        s->draw();
        seconds[r] = now() - start;
    }
    if (glGetError() != GL_NO_ERROR)
        fail("GL error");
    qsort(seconds, (size_t)runs, sizeof seconds[0], compare);
    printf("%s ns_per_vertex=%.3f vertices=%d runs=%d", s->name,
           1e9 * seconds[runs / 2] / vertices, vertices, runs);
    if (s->draw == draw_mesh)
        printf(" triangles=%d ns_per_triangle=%.3f", triangles,
               1e9 * seconds[runs / 2] / triangles);
#ifndef USE_OSMESA
    printf(" threads=%d", fflGetThreads());
#endif
    printf("\n");
    fflush(stdout);
    release();
}

#ifndef USE_OSMESA
/* The peak resident set (VmHWM), in KiB. */
static long peak_kib(void)
{
    char line[256];
    long kib = -1;
    FILE *f = fopen("/proc/self/status", "r");
    if (!f)
        fail("cannot read /proc/self/status");
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %ld", &kib) == 1)
            break;
    fclose(f);
    return kib;
}

/* How much the library's own memory grows over one call of n vertices (1 light): the
 * application's arrays are filled first and a small call reaches the library's baseline. */
static void run_memory(const char *name, int bulk, GLint n)
{
    long before, after;
    fill_points(n);
    out_a = allocate((bulk ? 4 : 8) * (size_t)n);
    if (bulk)
        out_b = allocate(4 * (size_t)n);
    setup(0, 0);
    fflSetThreads(0);
    if (bulk)
        light_bulk_n(WARMUP < n ? WARMUP : n);
    else
        draw_arrays_n(WARMUP < n ? WARMUP : n);
    before = peak_kib();
    if (bulk)
        light_bulk_n(n);
    else
        draw_arrays_n(n);
    after = peak_kib();
    if (glGetError() != GL_NO_ERROR || before < 0 || after < 0)
        fail("GL error or no VmHWM");
    printf("%s increase_kib=%ld vertices=%d threads=%d\n", name, after - before, n,
           fflGetThreads());
    release();
}
#endif

int main(int argc, char **argv)
{
    const char *name = argc > 1 ? argv[1] : "all";
    long n = argc > 2 ? atol(argv[2]) : 0; /* 0: the scene's own size */
    int runs = argc > 3 ? atoi(argv[3]) : 5, found = 0;
    size_t i;
#ifdef USE_OSMESA
    static GLubyte pixels[256 * 256 * 4];
    OSMesaContext osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!osmesa || !OSMesaMakeCurrent(osmesa, pixels, GL_UNSIGNED_BYTE, 256, 256))
        fail("no OSMesa context");
#endif
    if ((argc > 2 && n < 1) || n > 100000000)
        fail("VERTICES must be 1 to 100000000");
#ifndef USE_OSMESA
    if (!strcmp(name, "memory_bulk_10M") || !strcmp(name, "memory_arrays_10M")) {
        run_memory(name, !strcmp(name, "memory_bulk_10M"), n ? (GLint)n : 10000000);
        return 0;
    }
#endif
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        if (!strcmp(name, "all") || !strcmp(name, scenes[i].name)) {
            run_scene(&scenes[i], n ? (GLint)n : 1000000, runs);
            found = 1;
        }
    if (!found) {
        fprintf(stderr, "usage: %s SCENE|all [VERTICES [RUNS]]; scenes:", argv[0]);
        for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
            fprintf(stderr, " %s", scenes[i].name);
#ifndef USE_OSMESA
        fprintf(stderr, " memory_bulk_10M memory_arrays_10M");
#endif
        fprintf(stderr, "\n");
        return 2;
    }
    return 0;
}
