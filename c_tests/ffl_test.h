/*
 * ffl_test.h - the one header every C test program includes.
 *
 * One source, two builds:
 *   fflight: gcc -std=c99 ... -Iinclude prog.c target/debug/libfflight.a -lm -lpthread -ldl
 *   OSMesa:  gcc -std=c99 ... -DFFL_OSMESA prog.c -lOSMesa -lm
 *
 * Output protocol (read by tests/c_programs.rs):
 *   - Every line is a list of whitespace-separated tokens. A token that parses
 *     as a number is compared with a tolerance; any other token must be equal.
 *   - The last non-numeric token before a number is its label. Numbers labelled
 *     xy, xyz or xyzw are window coordinates (looser tolerance); every other
 *     number is compared with the color tolerance.
 *   - A line may contain the token `ref`: the labelled groups after it are the
 *     program's own double-precision evaluation of the spec, and each is
 *     checked against the group with the same label before `ref`.
 *     A `tol` value after `ref` sets that line's color tolerance (never
 *     below the harness's own) for comparisons involving OSMesa, which
 *     evaluates in float32: the reference knows when the color raises
 *     float rounding to a high power (shininess, spot exponent). fflight
 *     evaluates in double from its stored state and is always held to the
 *     harness's own tolerance against the reference.
 *   - A token `osmesa-exempt=<reason>` on such a line says OSMesa is known to
 *     differ from the spec there: the groups covered by `ref` are compared
 *     with the reference only, never across builds.
 *   - A token `clip-made` on a line says its vertex was made by clipping:
 *     its window coordinates get the harness's tolerance for such vertices
 *     (see CLIP_MADE_COORDINATE_TOLERANCE in tests/c_programs.rs).
 *   - A token `line-prim=<kind>` on a feedback segment line says the
 *     segment comes from a line primitive and the spec gives it the token
 *     <kind> (line_reset or line); the fflight build must have fed back
 *     exactly that (ffl_print_feedback_prims prints these marks).
 *   - Numbers labelled zhit are the depths of selection hit records, unsigned
 *     integers (z in [0, 1] scaled by 2^32 - 1): compared within 1e-5 of depth
 *     (HIT_DEPTH_TOLERANCE in tests/c_programs.rs), like window z.
 *   - A line `osmesa-known: <name>` in a program's header comment declares a
 *     known OSMesa-vs-spec difference the comparison accepts under a narrow
 *     rule. The only one is `line-reset`: fflight's `line_reset` where
 *     OSMesa has `line`, on a segment marked `line-prim=line_reset`.
 *   - The first line of each program is a comment naming its mode,
 *     "ffl-test: differential" (both builds, outputs compared), "ffl-test:
 *     fflight-only" (the program checks itself; exit status decides) or
 *     "ffl-test: osmesa-diff" (shows a known OSMesa-vs-spec difference: only
 *     the fflight build is checked against the program's reference).
 */
#ifndef FFL_TEST_H
#define FFL_TEST_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#ifdef FFL_OSMESA
/* <GL/glext.h> declares the GL 1.4 and 1.5 functions (glBlendFuncSeparate, ...) only then. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>
#define FFL_IMPL_NAME "osmesa"
#else
#include "fflight.h"
#define FFL_IMPL_NAME "fflight"
#endif

#define FFL_PI 3.14159265358979323846

/* Creates and binds the rendering context. fflight needs none (a default
 * context is made lazily per thread); OSMesa needs a context and a buffer.
 * Every program sets glViewport itself: the default viewports may differ. */
static inline void ffl_test_init(void)
{
#ifdef FFL_OSMESA
    static GLubyte color_buffer[64 * 64 * 4];
    /* 8 stencil bits, as fflight describes its framebuffer (GL_STENCIL_BITS): the
     * stencil reference is clamped to them. */
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (ctx == NULL) {
        fprintf(stderr, "OSMesaCreateContextExt failed\n");
        exit(2);
    }
    if (!OSMesaMakeCurrent(ctx, color_buffer, GL_UNSIGNED_BYTE, 64, 64)) {
        fprintf(stderr, "OSMesaMakeCurrent failed\n");
        exit(2);
    }
#endif
}

/* ---- canonical printing ------------------------------------------------ */

/* Prints " <value>" with 9 significant digits (enough to round-trip a float);
 * -0 prints as 0, NaN as nan, infinities as inf / -inf. */
static inline void ffl_pf(double v)
{
    if (v != v) {
        fputs(" nan", stdout);
    } else if (v == HUGE_VAL) {
        fputs(" inf", stdout);
    } else if (v == -HUGE_VAL) {
        fputs(" -inf", stdout);
    } else {
        if (v == 0.0)
            v = 0.0;
        printf(" %.9g", v);
    }
}

/* Prints " label v0 v1 ... v(n-1)". */
static inline void ffl_pfv(const char *label, const float *v, int n)
{
    int i;
    printf(" %s", label);
    for (i = 0; i < n; i++)
        ffl_pf(v[i]);
}

static inline void ffl_pdv(const char *label, const double *v, int n)
{
    int i;
    printf(" %s", label);
    for (i = 0; i < n; i++)
        ffl_pf(v[i]);
}

static inline const char *ffl_error_name(GLenum e)
{
    switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL_UNKNOWN_ERROR";
    }
}

/* Prints "<what> <error name>" for the next glGetError. */
static inline void ffl_print_error(const char *what)
{
    printf("%s %s\n", what, ffl_error_name(glGetError()));
}

/* ---- state queries --------------------------------------------------------- */

/* Prints "<what> i v0 ... v(n-1)": n values of glGetIntegerv (unwritten ones show -7). */
static inline void ffl_print_ints(const char *what, GLenum pname, int n)
{
    GLint v[16];
    int i;
    for (i = 0; i < 16; i++)
        v[i] = -7;
    glGetIntegerv(pname, v);
    printf("%s i", what);
    for (i = 0; i < n; i++)
        printf(" %d", (int)v[i]);
    printf("\n");
}

/* Prints "<what> f v0 ... v(n-1)": n values of glGetFloatv. */
static inline void ffl_print_floats(const char *what, GLenum pname, int n)
{
    GLfloat v[16];
    int i;
    for (i = 0; i < 16; i++)
        v[i] = -7.0f;
    glGetFloatv(pname, v);
    printf("%s", what);
    ffl_pfv("f", v, n);
    printf("\n");
}

/* Prints "<what> b v0 ... v(n-1)": n values of glGetBooleanv, and for one value also
 * glIsEnabled's answer when `cap` is set. */
static inline void ffl_print_bools(const char *what, GLenum pname, int n, int cap)
{
    GLboolean v[16];
    int i;
    for (i = 0; i < 16; i++)
        v[i] = 7;
    glGetBooleanv(pname, v);
    printf("%s b", what);
    for (i = 0; i < n; i++)
        printf(" %d", (int)v[i]);
    if (cap)
        printf(" enabled %d", (int)glIsEnabled(pname));
    printf("\n");
}

/* Number of values per vertex in a feedback buffer of the given type. */
static inline int ffl_feedback_vertex_size(GLenum type)
{
    switch (type) {
    case GL_2D: return 2;
    case GL_3D: return 3;
    case GL_3D_COLOR: return 7;
    case GL_3D_COLOR_TEXTURE: return 11;
    case GL_4D_COLOR_TEXTURE: return 12;
    default: return 0;
    }
}

/* Prints one fed-back vertex: " xy|xyz|xyzw ... rgba ... stuv ...". */
static inline void ffl_print_feedback_vertex(const GLfloat *v, GLenum type)
{
    switch (type) {
    case GL_2D: ffl_pfv("xy", v, 2); break;
    case GL_3D: ffl_pfv("xyz", v, 3); break;
    case GL_3D_COLOR: ffl_pfv("xyz", v, 3); ffl_pfv("rgba", v + 3, 4); break;
    case GL_3D_COLOR_TEXTURE:
        ffl_pfv("xyz", v, 3); ffl_pfv("rgba", v + 3, 4); ffl_pfv("strq", v + 7, 4);
        break;
    case GL_4D_COLOR_TEXTURE:
        ffl_pfv("xyzw", v, 4); ffl_pfv("rgba", v + 4, 4); ffl_pfv("strq", v + 8, 4);
        break;
    default: break;
    }
}

/* Prints a feedback buffer of n values, one line per token, each prefixed with
 * `prefix`. Returns 0 if the buffer parsed cleanly, 1 otherwise (a line
 * saying why is printed, so the outputs differ). */
static inline int ffl_print_feedback(const char *prefix, const GLfloat *buf, GLint n, GLenum type)
{
    int vs = ffl_feedback_vertex_size(type);
    GLint i = 0;
    while (i < n) {
        GLfloat token = buf[i++];
        int nverts = 0;
        const char *name = NULL;
        if (token == (GLfloat)GL_PASS_THROUGH_TOKEN) {
            if (i >= n) break;
            printf("%s pass", prefix);
            ffl_pf(buf[i++]);
            printf("\n");
            continue;
        } else if (token == (GLfloat)GL_POINT_TOKEN) {
            name = "point"; nverts = 1;
        } else if (token == (GLfloat)GL_LINE_TOKEN) {
            name = "line"; nverts = 2;
        } else if (token == (GLfloat)GL_LINE_RESET_TOKEN) {
            name = "line_reset"; nverts = 2;
        } else if (token == (GLfloat)GL_POLYGON_TOKEN) {
            if (i >= n) break;
            name = "polygon"; nverts = (int)buf[i++];
        } else if (token == (GLfloat)GL_BITMAP_TOKEN) {
            name = "bitmap"; nverts = 1;
        } else if (token == (GLfloat)GL_DRAW_PIXEL_TOKEN) {
            name = "draw_pixel"; nverts = 1;
        } else if (token == (GLfloat)GL_COPY_PIXEL_TOKEN) {
            name = "copy_pixel"; nverts = 1;
        } else {
            printf("%s unknown_token", prefix);
            ffl_pf(token);
            printf("\n");
            return 1;
        }
        printf("%s %s %d\n", prefix, name, nverts);
        while (nverts-- > 0) {
            if (i + vs > n) {
                printf("%s truncated\n", prefix);
                return 1;
            }
            printf("%s  v", prefix);
            ffl_print_feedback_vertex(buf + i, type);
            printf("\n");
            i += vs;
        }
    }
    if (i != n) {
        printf("%s truncated\n", prefix);
        return 1;
    }
    return 0;
}

/* ---- feedback of whole primitives ---------------------------------------- */

/* glPassThrough values from FFL_PRIM_MARK up mark the glBegin of primitive
 * number (value - FFL_PRIM_MARK) of a feedback pass, so the printer knows
 * which glBegin mode each token comes from. */
#define FFL_PRIM_MARK 1000.0f
#define FFL_MAX_PRIMS 1024

static inline const char *ffl_mode_name(GLenum mode)
{
    switch (mode) {
    case GL_POINTS: return "GL_POINTS";
    case GL_LINES: return "GL_LINES";
    case GL_LINE_STRIP: return "GL_LINE_STRIP";
    case GL_LINE_LOOP: return "GL_LINE_LOOP";
    case GL_TRIANGLES: return "GL_TRIANGLES";
    case GL_TRIANGLE_STRIP: return "GL_TRIANGLE_STRIP";
    case GL_TRIANGLE_FAN: return "GL_TRIANGLE_FAN";
    case GL_QUADS: return "GL_QUADS";
    case GL_QUAD_STRIP: return "GL_QUAD_STRIP";
    case GL_POLYGON: return "GL_POLYGON";
    default: return "unknown_mode";
    }
}

static inline int ffl_is_line_mode(GLenum mode)
{
    return mode == GL_LINES || mode == GL_LINE_STRIP || mode == GL_LINE_LOOP;
}

/* How many tokens of each kind a feedback pass returned. */
typedef struct {
    long points, lines, line_resets, polygons, polygon_vertices, passes;
} ffl_token_counts;

/* Called after each fed-back vertex is printed, before its newline, so a
 * program can add groups to the line (typically " ref rgba ..."): `mode` is
 * the glBegin mode the token comes from (0 if unknown), `token` the feedback
 * token, `vertices` the token's vertices (vertex_size values each), `k` the
 * vertex printed. */
typedef void (*ffl_vertex_note)(void *user, GLenum mode, GLenum token, const GLfloat *vertices,
                                int nverts, int k, GLenum type);

/* One feedback pass whose primitives are marked (see ffl_fb_begin). */
typedef struct {
    GLfloat *buf;
    GLsizei size;
    GLenum type;
    int nprims;
    GLenum modes[FFL_MAX_PRIMS];
    ffl_token_counts counts;
} ffl_fb;

/* Zeroes the struct (its token counts add up over every pass). */
static inline void ffl_fb_init(ffl_fb *fb)
{
    memset(fb, 0, sizeof *fb);
}

/* glFeedbackBuffer + glRenderMode(GL_FEEDBACK). */
static inline void ffl_fb_start(ffl_fb *fb, GLfloat *buf, GLsizei size, GLenum type)
{
    fb->buf = buf;
    fb->size = size;
    fb->type = type;
    fb->nprims = 0;
    glFeedbackBuffer(size, type, buf);
    glRenderMode(GL_FEEDBACK);
}

/* glPassThrough(marker): what follows is drawn as primitive `mode` (an array
 * draw, or the glBegin of ffl_fb_begin). */
static inline void ffl_fb_mark(ffl_fb *fb, GLenum mode)
{
    int id = fb->nprims < FFL_MAX_PRIMS ? fb->nprims++ : FFL_MAX_PRIMS - 1;
    fb->modes[id] = mode;
    glPassThrough(FFL_PRIM_MARK + (GLfloat)id);
}

/* A feedback pass for one array draw (no glBegin) marked as primitive `mode`. */
static inline void ffl_fb_draw_start(ffl_fb *fb, GLfloat *buf, GLsizei size, GLenum type,
                                     GLenum mode)
{
    ffl_fb_init(fb);
    ffl_fb_start(fb, buf, size, type);
    ffl_fb_mark(fb, mode);
}

/* glPassThrough(marker) then glBegin(mode). */
static inline void ffl_fb_begin(ffl_fb *fb, GLenum mode)
{
    ffl_fb_mark(fb, mode);
    glBegin(mode);
}

/*
 * Prints a feedback buffer like ffl_print_feedback, knowing which glBegin
 * each token comes from: a marker prints as "<prefix> begin <mode>", any
 * other pass-through as "<prefix> pass <value>". A segment from a line
 * primitive carries "line-prim=<kind>": the token the spec gives it (§3.4.2,
 * §5.3: the line stipple counter is reset before every segment of GL_LINES
 * and at the start of each strip or loop, so the first segment fed back of a
 * strip or loop is a GL_LINE_RESET_TOKEN, the rest GL_LINE_TOKEN; a segment
 * clipped away entirely advances nothing, so the reset goes to the first
 * segment that is fed back). Segments of polygon outlines carry nothing: how
 * a polygon is split is the implementation's choice. Counts the tokens into
 * `counts` (if given). Returns 0 if the buffer parsed cleanly.
 */
static inline int ffl_print_feedback_prims(const char *prefix, const GLfloat *buf, GLint n,
                                           GLenum type, const GLenum *modes, int nmodes,
                                           ffl_vertex_note note, void *user,
                                           ffl_token_counts *counts)
{
    int vs = ffl_feedback_vertex_size(type);
    GLenum mode = 0;
    int line_seen = 0;
    ffl_token_counts dummy;
    GLint i = 0;
    if (counts == NULL)
        counts = &dummy;
    while (i < n) {
        GLfloat token = buf[i++];
        GLenum kind;
        int nverts, k;
        const char *name;
        if (token == (GLfloat)GL_PASS_THROUGH_TOKEN) {
            GLfloat v;
            int id;
            if (i >= n)
                break;
            v = buf[i++];
            id = (int)(v - FFL_PRIM_MARK);
            if (v >= FFL_PRIM_MARK && (GLfloat)id == v - FFL_PRIM_MARK && id < nmodes) {
                mode = modes[id];
                line_seen = 0;
                printf("%s begin %s\n", prefix, ffl_mode_name(mode));
            } else {
                counts->passes++;
                printf("%s pass", prefix);
                ffl_pf(v);
                printf("\n");
            }
            continue;
        }
        if (token == (GLfloat)GL_POINT_TOKEN) {
            kind = GL_POINT_TOKEN; name = "point"; nverts = 1;
            counts->points++;
        } else if (token == (GLfloat)GL_LINE_TOKEN) {
            kind = GL_LINE_TOKEN; name = "line"; nverts = 2;
            counts->lines++;
        } else if (token == (GLfloat)GL_LINE_RESET_TOKEN) {
            kind = GL_LINE_RESET_TOKEN; name = "line_reset"; nverts = 2;
            counts->line_resets++;
        } else if (token == (GLfloat)GL_POLYGON_TOKEN) {
            if (i >= n)
                break;
            kind = GL_POLYGON_TOKEN; name = "polygon"; nverts = (int)buf[i++];
            counts->polygons++;
            counts->polygon_vertices += nverts;
        } else {
            printf("%s unknown_token", prefix);
            ffl_pf(token);
            printf("\n");
            return 1;
        }
        printf("%s %s %d", prefix, name, nverts);
        if (kind != GL_POINT_TOKEN && kind != GL_POLYGON_TOKEN && ffl_is_line_mode(mode)) {
            printf(" line-prim=%s", mode == GL_LINES || !line_seen ? "line_reset" : "line");
            line_seen = 1;
        }
        printf("\n");
        if (nverts < 0 || i + (GLint)nverts * vs > n) {
            printf("%s truncated\n", prefix);
            return 1;
        }
        for (k = 0; k < nverts; k++) {
            printf("%s  v", prefix);
            ffl_print_feedback_vertex(buf + i + k * vs, type);
            if (note != NULL)
                note(user, mode, kind, buf + i, nverts, k, type);
            printf("\n");
        }
        i += nverts * vs;
    }
    if (i != n) {
        printf("%s truncated\n", prefix);
        return 1;
    }
    return 0;
}

/* glRenderMode(GL_RENDER), then prints "<tag> count <n>" and the buffer
 * (ffl_print_feedback_prims). Returns 0 on success, 1 if the buffer
 * overflowed or did not parse. */
static inline int ffl_fb_finish(ffl_fb *fb, const char *tag, ffl_vertex_note note, void *user)
{
    GLint n = glRenderMode(GL_RENDER);
    printf("%s count %d\n", tag, (int)n);
    if (n < 0 || n > fb->size)
        return 1;
    return ffl_print_feedback_prims(tag, fb->buf, n, fb->type, fb->modes, fb->nprims, note,
                                    user, &fb->counts);
}

/* Called after each vertex ffl_print_feedback_segments_note prints, before its newline:
 * `vertices` the token's vertices (vertex_size values each), `nverts` their number, `k`
 * the vertex printed and `offset` its index in the buffer. */
typedef void (*ffl_segment_note)(void *user, GLenum token, const GLfloat *vertices, int nverts,
                                 int k, GLint offset, GLenum type);

/* Prints a feedback buffer of points, line segments and polygons (no pass-through
 * markers) like ffl_print_feedback, but every segment as "segment" whether its token is
 * GL_LINE_TOKEN or GL_LINE_RESET_TOKEN: for line primitives drawn by code that is not the
 * test's (libGLU's), where the stipple resets cannot be marked and OSMesa never feeds back
 * GL_LINE_RESET_TOKEN (docs/osmesa-differences.md, 1). `note` (may be NULL) adds to each
 * vertex line. */
static inline void ffl_print_feedback_segments_note(const char *tag, const GLfloat *buf, GLint n,
                                                    GLenum type, ffl_segment_note note,
                                                    void *user)
{
    GLint i = 0;
    int vs = ffl_feedback_vertex_size(type), k, count;
    printf("%s count %d\n", tag, (int)n);
    while (i < n) {
        GLenum token = (GLenum)buf[i++];
        const char *name;
        if (token == GL_POINT_TOKEN) {
            name = "point";
            count = 1;
        } else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN) {
            name = "segment";
            count = 2;
        } else if (token == GL_POLYGON_TOKEN && i < n) {
            name = "polygon";
            count = (int)buf[i++];
        } else {
            printf("%s unexpected token\n", tag);
            return;
        }
        printf("%s %s %d\n", tag, name, count);
        if (i + (GLint)count * vs > n) {
            printf("%s truncated\n", tag);
            return;
        }
        for (k = 0; k < count; k++) {
            printf("%s  v", tag);
            ffl_print_feedback_vertex(buf + i + k * vs, type);
            if (note != NULL)
                note(user, token, buf + i, count, k, i + k * vs, type);
            printf("\n");
        }
        i += count * vs;
    }
}

/* ffl_print_feedback_segments_note without a note. */
static inline void ffl_print_feedback_segments(const char *tag, const GLfloat *buf, GLint n,
                                               GLenum type)
{
    ffl_print_feedback_segments_note(tag, buf, n, type, NULL, NULL);
}

/* qsort order of GL_3D_COLOR vertices on coarse keys (1/256): two builds differ in the
 * last float digits. */
static inline int ffl_compare_vertices(const void *a, const void *b)
{
    const GLfloat *u = (const GLfloat *)a, *v = (const GLfloat *)b;
    int k;
    for (k = 0; k < 7; k++) {
        long ku = lround(u[k] * 256.0), kv = lround(v[k] * 256.0);
        if (ku != kv)
            return ku < kv ? -1 : 1;
    }
    return 0;
}

#define FFL_VERTEX_SET_MAX 65536

/* A GL_3D_COLOR feedback buffer of polygons printed as its number of polygons and its
 * distinct vertices in a fixed order: what any split of the same quads into triangles
 * shares (glEvalMesh2(GL_FILL): OSMesa draws triangle strips where the spec has quad
 * strips, docs/osmesa-differences.md, 20). */
static inline void ffl_print_vertex_set(const char *tag, const GLfloat *buf, GLint n)
{
    static GLfloat vertices[FFL_VERTEX_SET_MAX * 7];
    GLint i = 0;
    int polygons = 0, count = 0, k, distinct = 0;
    while (i < n && (GLenum)buf[i] == GL_POLYGON_TOKEN) {
        int nverts = (int)buf[i + 1];
        polygons++;
        i += 2;
        for (k = 0; k < nverts && i + 7 <= n && count < FFL_VERTEX_SET_MAX; k++, i += 7)
            memcpy(vertices + 7 * count++, buf + i, 7 * sizeof buf[0]);
    }
    printf("%s count %d polygons %d parsed %d\n", tag, (int)n, polygons, i == n);
    qsort(vertices, (size_t)count, 7 * sizeof vertices[0], ffl_compare_vertices);
    for (k = 0; k < count; k++) {
        if (k > 0 && ffl_compare_vertices(vertices + 7 * k, vertices + 7 * (k - 1)) == 0)
            continue;
        distinct++;
        printf("%s  v", tag);
        ffl_print_feedback_vertex(vertices + 7 * k, GL_3D_COLOR);
        printf("\n");
    }
    printf("%s distinct %d\n", tag, distinct);
}

/* ---- selection ------------------------------------------------------------ */

/* Prints the hit records of a selection pass that returned `hits` (glRenderMode's
 * value), one line per record: "<prefix> hit names <k> zhit <min> <max> stack
 * <names...>". The depths are the unsigned integers of the record (z scaled by
 * 2^32 - 1); the harness compares numbers labelled zhit within 1e-5 of depth.
 * After an overflow (-1) the `size` values written are printed the same way, the
 * last record cut short where the buffer ends ("cut"). Returns 0 if the records
 * parsed cleanly. */
static inline int ffl_print_hits(const char *prefix, const GLuint *buf, GLint hits, GLsizei size)
{
    GLint h, i = 0;
    printf("%s hits %d\n", prefix, (int)hits);
    for (h = 0; hits < 0 ? i < size : h < hits; h++) {
        GLuint k, names = buf[i++];
        printf("%s hit names %u zhit", prefix, names);
        for (k = 0; k < 2 && i < size; k++)
            printf(" %u", buf[i++]);
        printf(" stack");
        for (k = 0; k < names && i < size; k++)
            printf(" %u", buf[i++]);
        if (k < names || i > size) {
            printf(" cut\n");
            return hits >= 0;
        }
        printf("\n");
    }
    return 0;
}

/* ---- deterministic pseudo-random numbers (splitmix64) ------------------- */

typedef struct {
    uint64_t state;
} ffl_rng;

static inline void ffl_rng_seed(ffl_rng *r, uint64_t seed)
{
    r->state = seed;
}

static inline uint64_t ffl_rng_u64(ffl_rng *r)
{
    uint64_t z = (r->state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 bits. */
static inline double ffl_rng_unit(ffl_rng *r)
{
    return (double)(ffl_rng_u64(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform float in [lo, hi]: returned as a float so GL and the reference
 * consume exactly the same value. */
static inline float ffl_rng_float(ffl_rng *r, double lo, double hi)
{
    return (float)(lo + (hi - lo) * ffl_rng_unit(r));
}

/* Uniform integer in [0, n). */
static inline int ffl_rng_int(ffl_rng *r, int n)
{
    return (int)(ffl_rng_u64(r) % (uint64_t)n);
}

/* True with probability p. */
static inline int ffl_rng_chance(ffl_rng *r, double p)
{
    return ffl_rng_unit(r) < p;
}

/* ---- random shapes ------------------------------------------------------ */

/* Positions of `count` vertices for a glBegin(mode), around (cx, cy) with
 * radius about `size` in x and y and z in [-depth, depth]: a cloud for
 * points, lines and separate triangles; a zigzag band for triangle and quad
 * strips (every quad of a quad strip convex); a fan around its first vertex
 * at increasing angles; convex quads (each group of four on an ellipse) and a
 * convex polygon (on an ellipse, at increasing angles). Orientations (clockwise
 * or counterclockwise) are random. */
static inline void ffl_shape(ffl_rng *r, GLenum mode, int count, double cx, double cy,
                             double size, double depth, float (*p)[3])
{
    double dir = ffl_rng_unit(r) * 2.0 * FFL_PI, ux = cos(dir), uy = sin(dir);
    double sign = ffl_rng_chance(r, 0.5) ? 1.0 : -1.0;
    int k;
    for (k = 0; k < count; k++)
        p[k][2] = ffl_rng_float(r, -depth, depth);
    switch (mode) {
    case GL_TRIANGLE_STRIP:
    case GL_QUAD_STRIP:
        for (k = 0; k < count; k++) {
            double t = -size + 2.0 * size * ((double)(k / 2) + 0.3 * ffl_rng_unit(r)) /
                                 (double)(count / 2 + 1);
            double a = sign * (k % 2 ? -1.0 : 1.0) * size * (0.2 + 0.5 * ffl_rng_unit(r));
            p[k][0] = (float)(cx + t * ux - a * uy);
            p[k][1] = (float)(cy + t * uy + a * ux);
        }
        break;
    case GL_TRIANGLE_FAN:
    case GL_POLYGON: {
        double angle = 0.0, step = 2.0 * FFL_PI / (double)(count > 2 ? count : 3);
        double ex = size * (0.5 + 0.5 * ffl_rng_unit(r)), ey = size * (0.5 + 0.5 * ffl_rng_unit(r));
        for (k = 0; k < count; k++) {
            if (mode == GL_TRIANGLE_FAN && k == 0) {
                p[k][0] = (float)cx;
                p[k][1] = (float)cy;
                continue;
            }
            angle += step * (mode == GL_POLYGON ? 0.5 + 0.5 * ffl_rng_unit(r)
                                                : 0.3 + 1.2 * ffl_rng_unit(r));
            p[k][0] = (float)(cx + ex * cos(sign * angle) * ux - ey * sin(sign * angle) * uy);
            p[k][1] = (float)(cy + ex * cos(sign * angle) * uy + ey * sin(sign * angle) * ux);
        }
        break;
    }
    case GL_QUADS:
        for (k = 0; k < count; k++) {
            double qx = cx + size * (ffl_rng_unit(r) - 0.5), qy = cy + size * (ffl_rng_unit(r) - 0.5);
            double angle = ffl_rng_unit(r) * 2.0 * FFL_PI, e = size * (0.3 + 0.4 * ffl_rng_unit(r));
            int j;
            if (k + 4 > count) { /* the incomplete rest: anywhere */
                p[k][0] = (float)qx;
                p[k][1] = (float)qy;
                continue;
            }
            for (j = 0; j < 4; j++, k++) {
                angle += sign * (0.3 + 0.7 * ffl_rng_unit(r)) * FFL_PI / 2.0;
                p[k][0] = (float)(qx + e * cos(angle));
                p[k][1] = (float)(qy + 0.7 * e * sin(angle));
            }
            k--;
        }
        break;
    default:
        for (k = 0; k < count; k++) {
            p[k][0] = (float)(cx + size * (2.0 * ffl_rng_unit(r) - 1.0));
            p[k][1] = (float)(cy + size * (2.0 * ffl_rng_unit(r) - 1.0));
        }
        break;
    }
}

/* Ends a pass of ffl_fb_draw_start: prints it under `label`, then the error
 * flag. Returns ffl_fb_finish's result. */
static inline int ffl_fb_draw_finish(ffl_fb *fb, const char *label)
{
    int failed = ffl_fb_finish(fb, label, NULL, NULL);
    printf("%s error %s\n", label, ffl_error_name(glGetError()));
    return failed;
}

#endif /* FFL_TEST_H */
