/* The entry-point sweep (issue 9): every function of include/fflight.h called with hostile
 * arguments. tests/sweep.rs generates sweep_functions.h from the header (a caller per
 * function, its parameters' types and names, every GL_* value) and runs this program.
 *
 * Arguments: NULL pointers, zero, negative and huge counts and sizes, enums from the
 * header's whole list, likely ones and values no GL enum has, NaN and infinite floats.
 * Every pointer the program passes points into a buffer sized to what the spec lets the
 * call read or write (pointer_rule), its last byte against a PROT_NONE page, with canary
 * bytes before it and in the alignment slack after it: a read or write past the allowed
 * extent faults at once, even from the uninstrumented Rust library, and one before it
 * changes a canary. Pointers a command keeps (array pointers, the feedback and selection
 * buffers) point into persistent arenas laid out the same way; a draw is made only when
 * every element the spec lets it read lies in the array arena (arrays_fit), as an
 * application's would.
 *
 * Rules checked after every call (the table behind README's "Hostile input" section):
 *   R1  glGetError returns GL_NO_ERROR or one of GL's error codes.
 *   R2  a call that sets an error writes no byte of the buffers it was given (§2.5:
 *       "the offending command is ignored"), and no call writes outside the extent the
 *       spec gives it or into a const buffer (checked: the whole buffer and its canaries).
 *   R3  between glBegin and glEnd, every command §2.6.3 does not allow there is
 *       GL_INVALID_OPERATION (fflCapture*: README documents the same).
 *   R4  a GLsizei argument below zero, or a GLenum argument no GL enum has, is an error
 *       (outside glBegin/glEnd and display list compilation).
 *   R5  in GL_COMPILE mode, a command §5.4 compiles raises no error until the list runs
 *       (README: "Errors of compiled commands are raised when the list executes"), except
 *       glMultiDraw*, documented as checked at compile time, and glNewList (nested:
 *       GL_INVALID_OPERATION).
 *   R6  glGetString returns NULL or a NUL-terminated string.
 *   R7  a pname-taking query accepts only the pnames of its table in pname_counts.h (the
 *       GL 1.5 state tables' counts), and writes each one's count of values: beyond the
 *       count its buffer holds canaries up to the most any pname takes (R2 reports a write
 *       there), and every (query, header enum) pair is tried once with exact counts.
 * Phases: each function SWEEP_ROUNDS times in each situation (outside, between
 * glBegin/glEnd, compiling a GL_COMPILE list, then calling the list, and
 * GL_COMPILE_AND_EXECUTE), then random functions in random order with random arguments
 * without any reset for SWEEP_SECONDS (or SWEEP_CALLS calls). The seed is fixed
 * (SWEEP_SEED). A call running longer than SWEEP_CALL_SECONDS (10) fails, its arguments printed. */
#include "fflight.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

union sweep_arg {
    long long i;
    double f;
    void *p;
};

enum sweep_kind {
    SWEEP_NONE,
    SWEEP_ENUM,
    SWEEP_BOOLEAN,
    SWEEP_BITFIELD,
    SWEEP_INTEGER,
    SWEEP_SIZE,
    SWEEP_POINTER_SIZED,
    SWEEP_REAL,
    SWEEP_POINTER,
    SWEEP_POINTER_ARRAY
};
enum { SWEEP_SIGNED, SWEEP_UNSIGNED };
enum { SWEEP_RETURNS_NOTHING, SWEEP_RETURNS_VALUE, SWEEP_RETURNS_POINTER };

#define MAX_PARAMS 20
struct sweep_param {
    int kind;
    size_t size; /* of the value, or of one pointed-to element */
    int constant;
    int sign;
    const char *type;
    const char *name;
};
struct sweep_function {
    const char *name;
    void (*call)(union sweep_arg *, union sweep_arg *);
    int count;
    int returns;
    struct sweep_param params[MAX_PARAMS];
};

#include "sweep_functions.h"
#include "pname_counts.h"

/* ---- deterministic random numbers (splitmix64) ---- */
static unsigned long long rng_state;
static unsigned long long next_u64(void)
{
    unsigned long long z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static unsigned below(unsigned n) { return (unsigned)(next_u64() % n); }

/* ---- failure reporting ---- */
static int current_fn = -1;
static union sweep_arg current_args[MAX_PARAMS];
static const char *current_situation = "";
static long long calls_made;
static unsigned call_seconds = 10; /* SWEEP_CALL_SECONDS: longer under valgrind */

static void print_call(FILE *out)
{
    int k;
    const struct sweep_function *f;
    if (current_fn < 0)
        return;
    f = &SWEEP_FUNCTIONS[current_fn];
    fprintf(out, "  call %lld (%s): %s(", calls_made, current_situation, f->name);
    for (k = 0; k < f->count; k++) {
        const struct sweep_param *p = &f->params[k];
        if (k)
            fprintf(out, ", ");
        if (p->kind == SWEEP_REAL)
            fprintf(out, "%s=%g", p->name, current_args[k].f);
        else if (p->kind == SWEEP_POINTER || p->kind == SWEEP_POINTER_ARRAY)
            fprintf(out, "%s=%p", p->name, current_args[k].p);
        else
            fprintf(out, "%s=%lld (0x%llx)", p->name, current_args[k].i,
                    (unsigned long long)current_args[k].i);
    }
    fprintf(out, ")\n");
}

static int failures;
static unsigned char reported[SWEEP_FUNCTION_COUNT + 1][8];
/* Counts a failure; prints the first of each rule for each function. */
static void fail(const char *rule, const char *what)
{
    int row = current_fn < 0 ? SWEEP_FUNCTION_COUNT : current_fn;
    int column = rule[0] == 'R' ? rule[1] - '0' : 0;
    failures++;
    if (!reported[row][column & 7]++) {
        printf("FAIL %s: %s\n", rule, what);
        print_call(stdout);
    }
}

static void on_signal(int sig)
{
    /* Not async-signal-safe, but the process is ending anyway and the message matters. */
    printf("FATAL signal %d (%s)\n", sig, sig == SIGALRM ? "the call ran longer than SWEEP_CALL_SECONDS"
                                                        : "crash");
    print_call(stdout);
    fflush(stdout);
    _exit(3);
}

/* ---- guarded buffers: the allowed extent ends against a PROT_NONE page ---- */
#define CANARY 0xA5
#define PAGE 4096
#define SLOT_BYTES (8u << 20) /* the largest buffer one pointer gets; larger: NULL */
#define LEAD 64               /* canary bytes checked before a buffer */

struct region {
    unsigned char *base; /* start of the readable/writable pages */
    size_t bytes;        /* their size; a PROT_NONE page follows (and precedes) */
};

static struct region map_region(size_t bytes)
{
    struct region r;
    unsigned char *all;
    bytes = (bytes + PAGE - 1) / PAGE * PAGE;
    all = mmap(NULL, bytes + 2 * PAGE, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (all == MAP_FAILED || mprotect(all + PAGE, bytes, PROT_READ | PROT_WRITE) != 0) {
        perror("mmap");
        exit(2);
    }
    r.base = all + PAGE;
    r.bytes = bytes;
    return r;
}

/* One pointer argument's buffer. */
struct slot {
    struct region region;
    unsigned char *data;  /* what the call gets */
    size_t bytes;         /* the extent the spec allows */
    size_t checked_from;  /* canaries from here ... */
    int output;           /* the call may write [data, data + bytes) */
    unsigned char *saved; /* the bytes before the call, for const and failed calls */
};
static struct slot slots[MAX_PARAMS + 1];
static unsigned char saved_bytes[MAX_PARAMS + 1][SLOT_BYTES / 64 + LEAD + 16];

static size_t element_align(size_t size)
{
    if (size >= 8)
        return 8;
    if (size >= 4)
        return 4;
    if (size >= 2)
        return 2;
    return 1;
}

/* Places a buffer of `bytes` (the allowed extent) `room` bytes before the slot's end, the
 * bytes between them canaries; fills it by `fill`. */
static void *slot_buffer_room(int k, size_t bytes, size_t room, size_t element, int output, int fill)
{
    struct slot *s = &slots[k];
    size_t align = element_align(element);
    size_t rounded = ((room > bytes ? room : bytes) + align - 1) / align * align;
    size_t i, lead;
    if (!s->region.base)
        s->region = map_region(SLOT_BYTES);
    s->data = s->region.base + s->region.bytes - rounded;
    s->bytes = bytes;
    s->output = output;
    lead = (size_t)(s->data - s->region.base) < LEAD ? (size_t)(s->data - s->region.base) : LEAD;
    s->checked_from = (size_t)(s->data - s->region.base) - lead;
    memset(s->region.base + s->checked_from, CANARY, lead);
    memset(s->data + bytes, CANARY, rounded - bytes);
    if (output) {
        memset(s->data, CANARY, bytes);
    } else if (fill == 1) {
        /* Small non-negative values, as indices and list names are. */
        for (i = 0; i < bytes; i++)
            s->data[i] = (unsigned char)(i % element == 0 ? below(6) : 0);
    } else {
        for (i = 0; i + 8 <= bytes; i += 8) {
            unsigned long long v = next_u64();
            switch (below(8)) {
            case 0: { double d = NAN; memcpy(&v, &d, 8); break; }
            case 1: { float f[2] = { INFINITY, -INFINITY }; memcpy(&v, f, 8); break; }
            case 2: { float f[2] = { 1.0f, 0.5f }; memcpy(&v, f, 8); break; }
            case 3: v = 0; break;
            case 4: v &= 0x0000000300000003ull; break;
            default: break;
            }
            memcpy(s->data + i, &v, 8);
        }
        for (; i < bytes; i++)
            s->data[i] = (unsigned char)next_u64();
    }
    return s->data;
}

/* Places a buffer of `bytes` against the slot's end; fills it by `fill`. */
static void *slot_buffer(int k, size_t bytes, size_t element, int output, int fill)
{
    return slot_buffer_room(k, bytes, bytes, element, output, fill);
}

static size_t saved_count(const struct slot *s)
{
    size_t n = (size_t)(s->data - s->region.base) - s->checked_from + s->bytes;
    return n < sizeof saved_bytes[0] ? n : sizeof saved_bytes[0];
}

static void slot_save(int k)
{
    struct slot *s = &slots[k];
    memcpy(saved_bytes[k], s->region.base + s->checked_from, saved_count(s));
}

/* R2: canaries intact; a const buffer, or any buffer of a failed call, unchanged. */
static void slot_check(int k, int errored, const char *param)
{
    struct slot *s = &slots[k];
    unsigned char *end = s->region.base + s->region.bytes;
    unsigned char *p;
    char what[200];
    for (p = s->region.base + s->checked_from; p < s->data; p++)
        if (*p != CANARY) {
            snprintf(what, sizeof what, "%s: byte %ld before the buffer written", param,
                     (long)(p - s->data));
            fail("R2", what);
            return;
        }
    for (p = s->data + s->bytes; p < end; p++)
        if (*p != CANARY) {
            snprintf(what, sizeof what, "%s: byte %ld written, the spec allows %lu", param,
                     (long)(p - s->data), (unsigned long)s->bytes);
            fail("R2", what);
            return;
        }
    if ((!s->output || errored) &&
        memcmp(saved_bytes[k], s->region.base + s->checked_from, saved_count(s)) != 0) {
        snprintf(what, sizeof what, "%s: %s buffer changed", param,
                 s->output ? "a failed call's" : "a const");
        fail("R2", what);
    }
}

/* ---- persistent arenas: array elements, feedback, selection, element indices ---- */
#define ARRAY_ARENA_BYTES (1u << 20)
#define FEEDBACK_CAPACITY 65536
#define INDEX_ARENA_BYTES 4096
static struct region array_arena, feedback_arena, select_arena, index_arena;

static int in_array_arena(const void *p)
{
    const unsigned char *c = p;
    return c >= array_arena.base && c < array_arena.base + array_arena.bytes;
}

/* ---- state queries for the size rules ---- */
static GLint get_int(GLenum pname)
{
    GLint v[16] = { 0 };
    glGetIntegerv(pname, v);
    return v[0];
}

/* Bytes §3.6.4 / §4.3.2 let a transfer of a w x h x d image touch, with the pack or unpack
 * modes in force; -1 when the format or type is not one (the call must fail). */
static long long image_bytes(int pack, long long w, long long h, long long d, int dims,
                             GLenum format, GLenum type)
{
    long long n, s, l, a, k, rows, skip_pixels, skip_rows, skip_images, image_height;
    int packed = 0;
    switch (format) {
    case GL_COLOR_INDEX: case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT: case GL_RED:
    case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: n = 1; break;
    case GL_LUMINANCE_ALPHA: n = 2; break;
    case GL_RGB: case GL_BGR: n = 3; break;
    case GL_RGBA: case GL_BGRA: n = 4; break;
    default: return -1;
    }
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: s = 1; break;
    case GL_UNSIGNED_SHORT: case GL_SHORT: s = 2; break;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: s = 4; break;
    case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV: s = 1; packed = 1; break;
    case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV: s = 2; packed = 1; break;
    case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV: s = 4; packed = 1; break;
    case GL_BITMAP: s = 0; break;
    default: return -1;
    }
    if (w < 0 || h < 0 || d < 0)
        return -1;
    if (w == 0 || h == 0 || d == 0)
        return 0;
    l = get_int(pack ? GL_PACK_ROW_LENGTH : GL_UNPACK_ROW_LENGTH);
    skip_pixels = get_int(pack ? GL_PACK_SKIP_PIXELS : GL_UNPACK_SKIP_PIXELS);
    skip_rows = get_int(pack ? GL_PACK_SKIP_ROWS : GL_UNPACK_SKIP_ROWS);
    a = get_int(pack ? GL_PACK_ALIGNMENT : GL_UNPACK_ALIGNMENT);
    skip_images = dims == 3 ? get_int(pack ? GL_PACK_SKIP_IMAGES : GL_UNPACK_SKIP_IMAGES) : 0;
    image_height = get_int(pack ? GL_PACK_IMAGE_HEIGHT : GL_UNPACK_IMAGE_HEIGHT);
    if (l <= 0)
        l = w;
    if (a <= 0)
        a = 1;
    if (type == GL_BITMAP) {
        if (format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX)
            return -1;
        k = a * ((l + 8 * a - 1) / (8 * a));
        return (skip_rows + h - 1) * k + (skip_pixels + w + 7) / 8;
    }
    if (packed)
        n = 1;
    k = s >= a ? n * l : a / s * ((s * n * l + a - 1) / a);
    rows = image_height > 0 && dims == 3 ? image_height : h;
    return s * ((skip_images + d - 1) * k * rows + (skip_rows + h - 1) * k + (skip_pixels + w) * n);
}

static long long type_bytes(GLenum type)
{
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: return 2;
    case GL_3_BYTES: return 3;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: return 4;
    case GL_DOUBLE: return 8;
    default: return -1;
    }
}

/* Values of one control point of an evaluator map (0: no such target). */
static long long map_values(GLenum target)
{
    switch (target) {
    case GL_MAP1_INDEX: case GL_MAP2_INDEX: case GL_MAP1_TEXTURE_COORD_1:
    case GL_MAP2_TEXTURE_COORD_1: return 1;
    case GL_MAP1_TEXTURE_COORD_2: case GL_MAP2_TEXTURE_COORD_2: return 2;
    case GL_MAP1_VERTEX_3: case GL_MAP2_VERTEX_3: case GL_MAP1_NORMAL: case GL_MAP2_NORMAL:
    case GL_MAP1_TEXTURE_COORD_3: case GL_MAP2_TEXTURE_COORD_3: return 3;
    case GL_MAP1_VERTEX_4: case GL_MAP2_VERTEX_4: case GL_MAP1_COLOR_4: case GL_MAP2_COLOR_4:
    case GL_MAP1_TEXTURE_COORD_4: case GL_MAP2_TEXTURE_COORD_4: return 4;
    default: return 0;
    }
}

static int is_map2(GLenum target) { return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4; }

/* The size of the pixel map `map` (0 for no such map). */
static long long pixel_map_size(GLenum map)
{
    if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A)
        return 0;
    return get_int(GL_PIXEL_MAP_I_TO_I_SIZE + (map - GL_PIXEL_MAP_I_TO_I));
}

/* ---- what the spec lets each pointer parameter be: bytes, or an arena ---- */
#define NO_RULE (LLONG_MIN + 2)
#define ARRAY_POINTER (LLONG_MIN + 3)
#define FEEDBACK_POINTER (LLONG_MIN + 4)
#define SELECT_POINTER (LLONG_MIN + 5)
#define CONTEXT_POINTER (LLONG_MIN + 6)
#define INDEX_POINTERS (LLONG_MIN + 7)
#define ELEMENT_INDICES (LLONG_MIN + 8)

static int starts(const char *s, const char *prefix) { return strncmp(s, prefix, strlen(prefix)) == 0; }
static int same(const char *a, const char *b) { return strcmp(a, b) == 0; }

/* Commands whose vector form reads N values, N from the name (glColor3fv: 3). */
static const char *const VECTOR_PREFIXES[] = {
    "glVertex", "glColor", "glSecondaryColor", "glNormal", "glTexCoord", "glMultiTexCoord",
    "glRasterPos", "glWindowPos", "glEvalCoord", "glRect", "glIndex", "glFogCoord", "glEdgeFlag",
};

static long long vector_count(const char *name)
{
    size_t i, len = strlen(name);
    static const char *const suffixes[] = { "bv", "sv", "iv", "fv", "dv", "ubv", "usv", "uiv", "xv", "v" };
    for (i = 0; i < sizeof VECTOR_PREFIXES / sizeof VECTOR_PREFIXES[0]; i++) {
        const char *rest;
        size_t j;
        if (!starts(name, VECTOR_PREFIXES[i]))
            continue;
        rest = name + strlen(VECTOR_PREFIXES[i]);
        {
            long long count = 1;
            if (*rest >= '1' && *rest <= '4')
                count = *rest++ - '0';
            for (j = 0; j < sizeof suffixes / sizeof suffixes[0]; j++)
                if (same(rest, suffixes[j]))
                    return same(VECTOR_PREFIXES[i], "glRect") ? 2 : count;
        }
    }
    (void)len;
    return 0;
}

/* Matrices and clip planes: how many values they read or write. */
struct family {
    const char *prefix;
    long long values;
};
static const struct family PNAME_FAMILIES[] = {
    { "glLoadMatrix", 16 }, { "glMultMatrix", 16 }, { "glLoadTransposeMatrix", 16 },
    { "glMultTransposeMatrix", 16 }, { "glClipPlane", 4 }, { "glGetClipPlane", 4 },
};

/* The entry of `list` whose prefix starts `name`, or NULL. */
static const struct pname_query *pname_entry(const struct pname_query *list, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (starts(name, list[i].prefix))
            return &list[i];
    return NULL;
}

/* The pname table of a pname-taking query (tests/sweep/pname_counts.h), or NULL. */
static const struct pname_query *pname_query(const char *name)
{
    return pname_entry(PNAME_QUERIES, sizeof PNAME_QUERIES / sizeof PNAME_QUERIES[0], name);
}

/* The pname table of a command setting a pname's values, or NULL. */
static const struct pname_query *pname_setter(const char *name)
{
    return pname_entry(PNAME_SETTERS, sizeof PNAME_SETTERS / sizeof PNAME_SETTERS[0], name);
}

/* The index of fn's parameter named `pname` (-1: none). */
static int pname_index(int fn)
{
    int k;
    for (k = 0; k < SWEEP_FUNCTIONS[fn].count; k++)
        if (same(SWEEP_FUNCTIONS[fn].params[k].name, "pname"))
            return k;
    return -1;
}

#define PNAME_UNKNOWN (-2)
/* How many values the state tables give `pname` of query q; PNAME_UNKNOWN if none. */
static int pname_count(const struct pname_query *q, GLenum pname)
{
    size_t i;
    for (i = 0; i < q->size; i++)
        if (q->table[i].pname == pname)
            return q->table[i].count == PNAME_COMPRESSED_FORMATS
                       ? (int)get_int(GL_NUM_COMPRESSED_TEXTURE_FORMATS)
                       : q->table[i].count;
    return PNAME_UNKNOWN;
}

static long long pname_values(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof PNAME_FAMILIES / sizeof PNAME_FAMILIES[0]; i++)
        if (starts(name, PNAME_FAMILIES[i].prefix) && name[strlen(name) - 1] != 'f' &&
            name[strlen(name) - 1] != 'i' && name[strlen(name) - 1] != 'x')
            return PNAME_FAMILIES[i].values;
    for (i = 0; i < sizeof PNAME_FAMILIES / sizeof PNAME_FAMILIES[0]; i++)
        if (starts(name, PNAME_FAMILIES[i].prefix))
            return PNAME_FAMILIES[i].values; /* glLoadMatrixf, glClipPlanef ... */
    return 0;
}

static long long level_dimension(GLenum target, GLint level, GLenum pname)
{
    GLint v = -1;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
}

/* Bytes the spec lets parameter k of function fn touch, given the other arguments and the
 * state (queried here); one of the arena codes; NO_RULE when the sweep knows none. */
static long long pointer_rule(int fn, const union sweep_arg *a, int k)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    const char *name = f->name;
    const char *param = f->params[k].name;
    long long e = (long long)f->params[k].size, n;
#define ARG(x) (a[x].i)
#define SIZE_ARG(x) ((long long)(GLsizei)a[x].i)
#define ENUM_ARG(x) ((GLenum)a[x].i)
    if ((n = vector_count(name)) > 0)
        return n * e;
    if (strstr(name, "Pointer") && !starts(name, "glGet") && same(param, "ptr"))
        return ARRAY_POINTER;
    if (same(name, "glInterleavedArrays"))
        return ARRAY_POINTER;
    if (same(name, "glFeedbackBuffer"))
        return FEEDBACK_POINTER;
    if (same(name, "glSelectBuffer"))
        return SELECT_POINTER;
    if (same(name, "fflMakeCurrent") || same(name, "fflDestroyContext"))
        return CONTEXT_POINTER;
    if ((pname_query(name) || pname_setter(name)) && pname_index(fn) >= 0) {
        /* The pname's count from the state tables; a pname they lack gets the family's
         * room (make_call fails a query that accepts it). */
        const struct pname_query *q = pname_query(name) ? pname_query(name) : pname_setter(name);
        int count = pname_count(q, ENUM_ARG(pname_index(fn)));
        return (count == PNAME_UNKNOWN ? q->room : count) * e;
    }
    if ((n = pname_values(name)) > 0)
        return n * e;
    if (same(name, "glTexImage1D"))
        return image_bytes(0, SIZE_ARG(3), 1, 1, 1, ENUM_ARG(5), ENUM_ARG(6));
    if (same(name, "glTexImage2D"))
        return image_bytes(0, SIZE_ARG(3), SIZE_ARG(4), 1, 2, ENUM_ARG(6), ENUM_ARG(7));
    if (same(name, "glTexImage3D"))
        return image_bytes(0, SIZE_ARG(3), SIZE_ARG(4), SIZE_ARG(5), 3, ENUM_ARG(7), ENUM_ARG(8));
    if (same(name, "glTexSubImage1D"))
        return image_bytes(0, SIZE_ARG(3), 1, 1, 1, ENUM_ARG(4), ENUM_ARG(5));
    if (same(name, "glTexSubImage2D"))
        return image_bytes(0, SIZE_ARG(4), SIZE_ARG(5), 1, 2, ENUM_ARG(6), ENUM_ARG(7));
    if (same(name, "glTexSubImage3D"))
        return image_bytes(0, SIZE_ARG(5), SIZE_ARG(6), SIZE_ARG(7), 3, ENUM_ARG(8), ENUM_ARG(9));
    if (same(name, "glDrawPixels"))
        return image_bytes(0, SIZE_ARG(0), SIZE_ARG(1), 1, 2, ENUM_ARG(2), ENUM_ARG(3));
    if (same(name, "glReadPixels"))
        return image_bytes(1, SIZE_ARG(2), SIZE_ARG(3), 1, 2, ENUM_ARG(4), ENUM_ARG(5));
    if (same(name, "glBitmap"))
        return image_bytes(0, SIZE_ARG(0), SIZE_ARG(1), 1, 2, GL_COLOR_INDEX, GL_BITMAP);
    if (same(name, "glPolygonStipple"))
        return image_bytes(0, 32, 32, 1, 2, GL_COLOR_INDEX, GL_BITMAP);
    if (same(name, "glGetPolygonStipple"))
        return image_bytes(1, 32, 32, 1, 2, GL_COLOR_INDEX, GL_BITMAP);
    if (same(name, "glColorTable"))
        return image_bytes(0, SIZE_ARG(2), 1, 1, 1, ENUM_ARG(3), ENUM_ARG(4));
    if (same(name, "glColorSubTable"))
        return image_bytes(0, SIZE_ARG(2), 1, 1, 1, ENUM_ARG(3), ENUM_ARG(4));
    if (same(name, "glConvolutionFilter1D"))
        return image_bytes(0, SIZE_ARG(2), 1, 1, 1, ENUM_ARG(3), ENUM_ARG(4));
    if (same(name, "glConvolutionFilter2D"))
        return image_bytes(0, SIZE_ARG(2), SIZE_ARG(3), 1, 2, ENUM_ARG(4), ENUM_ARG(5));
    if (same(name, "glSeparableFilter2D"))
        return image_bytes(0, k == 6 ? SIZE_ARG(2) : SIZE_ARG(3), 1, 1, 1, ENUM_ARG(4), ENUM_ARG(5));
    if (same(name, "glGetTexImage")) {
        GLenum target = ENUM_ARG(0);
        GLint level = (GLint)ARG(1);
        long long w = level_dimension(target, level, GL_TEXTURE_WIDTH);
        long long h = level_dimension(target, level, GL_TEXTURE_HEIGHT);
        long long d = level_dimension(target, level, GL_TEXTURE_DEPTH);
        int dims = target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
        if (w < 0 || h < 0 || d < 0)
            return 0;
        return image_bytes(1, w, dims >= 2 ? h : 1, dims == 3 ? d : 1, dims, ENUM_ARG(2), ENUM_ARG(3));
    }
    if (same(name, "glGetColorTable")) {
        GLint w = -1;
        glGetColorTableParameteriv(ENUM_ARG(0), GL_COLOR_TABLE_WIDTH, &w);
        return image_bytes(1, w, 1, 1, 1, ENUM_ARG(1), ENUM_ARG(2));
    }
    if (same(name, "glGetConvolutionFilter") || same(name, "glGetSeparableFilter")) {
        GLint w = -1, h = -1;
        glGetConvolutionParameteriv(ENUM_ARG(0), GL_CONVOLUTION_WIDTH, &w);
        glGetConvolutionParameteriv(ENUM_ARG(0), GL_CONVOLUTION_HEIGHT, &h);
        if (same(name, "glGetSeparableFilter"))
            return k == 3 ? image_bytes(1, w, 1, 1, 1, ENUM_ARG(1), ENUM_ARG(2))
                 : k == 4 ? image_bytes(1, h, 1, 1, 1, ENUM_ARG(1), ENUM_ARG(2)) : 0;
        return image_bytes(1, w, ENUM_ARG(0) == GL_CONVOLUTION_1D ? 1 : h, 1, 2, ENUM_ARG(1), ENUM_ARG(2));
    }
    if (same(name, "glGetHistogram")) {
        GLint w = -1;
        glGetHistogramParameteriv(ENUM_ARG(0), GL_HISTOGRAM_WIDTH, &w);
        return image_bytes(1, w, 1, 1, 1, ENUM_ARG(2), ENUM_ARG(3));
    }
    if (same(name, "glGetMinmax"))
        return image_bytes(1, 2, 1, 1, 1, ENUM_ARG(2), ENUM_ARG(3));
    if (starts(name, "glCompressedTex"))
        return SIZE_ARG(f->count - 2);
    if (same(name, "glGetCompressedTexImage"))
        return 0; /* fflight has no compressed format: always GL_INVALID_OPERATION */
    if (same(name, "glCallLists"))
        return SIZE_ARG(0) * type_bytes(ENUM_ARG(1));
    if (starts(name, "glGen") && !same(name, "glGenLists"))
        return SIZE_ARG(0) * e;
    if (starts(name, "glDelete") && !same(name, "glDeleteLists"))
        return SIZE_ARG(0) * e;
    if (same(name, "glAreTexturesResident") || same(name, "glPrioritizeTextures"))
        return SIZE_ARG(0) * e;
    if (same(name, "glBufferData"))
        return (long long)(GLsizeiptr)ARG(1);
    if (same(name, "glBufferSubData") || same(name, "glGetBufferSubData"))
        return (long long)(GLsizeiptr)ARG(2);
    if (starts(name, "glPixelMap"))
        return SIZE_ARG(1) * e;
    if (starts(name, "glGetPixelMap"))
        return pixel_map_size(ENUM_ARG(0)) * e;
    if (same(name, "glMap1f") || same(name, "glMap1d")) {
        long long values = map_values(ENUM_ARG(0)), stride = (GLint)ARG(3), order = (GLint)ARG(4);
        if (!values || stride < values || order < 1)
            return 0;
        return ((order - 1) * stride + values) * e;
    }
    if (same(name, "glMap2f") || same(name, "glMap2d")) {
        long long values = map_values(ENUM_ARG(0));
        long long ustride = (GLint)ARG(3), uorder = (GLint)ARG(4);
        long long vstride = (GLint)ARG(7), vorder = (GLint)ARG(8);
        if (!values || ustride < values || vstride < values || uorder < 1 || vorder < 1)
            return 0;
        return ((uorder - 1) * ustride + (vorder - 1) * vstride + values) * e;
    }
    if (starts(name, "glGetMap")) {
        GLenum target = ENUM_ARG(0), query = ENUM_ARG(1);
        long long values = map_values(target);
        if (!values)
            return 0;
        if (query == GL_ORDER)
            return (is_map2(target) ? 2 : 1) * e;
        if (query == GL_DOMAIN)
            return (is_map2(target) ? 4 : 2) * e;
        if (query == GL_COEFF) {
            GLint order[2] = { 0, 1 };
            glGetMapiv(target, GL_ORDER, order);
            return (long long)order[0] * (is_map2(target) ? order[1] : 1) * values * e;
        }
        return 0;
    }
    if (same(name, "glMultiDrawArrays"))
        return SIZE_ARG(3) * e;
    if (same(name, "glMultiDrawElements"))
        return k == 3 ? INDEX_POINTERS : SIZE_ARG(4) * e;
    if (same(name, "glDrawElements") || same(name, "glDrawRangeElements"))
        return ELEMENT_INDICES;
    if (same(name, "fflCaptureReadVertices") || same(name, "fflCaptureReadPrimitives"))
        return (long long)(GLuint)ARG(1) * e;
    if (same(name, "fflCaptureReadTexCoords"))
        return (long long)(GLuint)ARG(2) * 4 * e;
    if (same(name, "fflLightVertices")) {
        long long count = SIZE_ARG(0), size = (GLint)ARG(1), stride = SIZE_ARG(k + 1), element;
        if (k == 2)
            element = size * 4;
        else if (k == 4)
            element = 12;
        else
            element = 16;
        if (count <= 0 || stride < 0 || size < 2 || size > 4)
            return 0;
        return (count - 1) * (stride ? stride : element) + element;
    }
    return NO_RULE;
#undef ARG
#undef SIZE_ARG
#undef ENUM_ARG
}

/* ---- contexts the sweep may pass to fflMakeCurrent / fflDestroyContext ---- */
#define MAX_CONTEXTS 4
static FflContext *main_context;
static FflContext *contexts[MAX_CONTEXTS];
static int context_count;

static void remember_context(FflContext *c)
{
    if (!c)
        return;
    if (context_count == MAX_CONTEXTS) {
        FflContext *old = contexts[0];
        memmove(contexts, contexts + 1, sizeof contexts[0] * (MAX_CONTEXTS - 1));
        context_count--;
        fflMakeCurrent(NULL);
        fflDestroyContext(old);
    }
    contexts[context_count++] = c;
}

static void forget_context(FflContext *c)
{
    int i;
    for (i = 0; i < context_count; i++)
        if (contexts[i] == c) {
            memmove(contexts + i, contexts + i + 1, sizeof contexts[0] * (size_t)(context_count - i - 1));
            context_count--;
            return;
        }
}

/* ---- the arrays a draw may read: every element it can reach lies in the arena ---- */
struct client_array {
    GLenum cap, pointer, size, type, stride, binding;
    GLint fixed_size; /* 0: the size query */
};
static const struct client_array CLIENT_ARRAYS[] = {
    { GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_POINTER, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE,
      GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY_BUFFER_BINDING, 0 },
    { GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_POINTER, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
      GL_NORMAL_ARRAY_BUFFER_BINDING, 3 },
    { GL_COLOR_ARRAY, GL_COLOR_ARRAY_POINTER, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE,
      GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY_BUFFER_BINDING, 0 },
    { GL_SECONDARY_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY_POINTER, GL_SECONDARY_COLOR_ARRAY_SIZE,
      GL_SECONDARY_COLOR_ARRAY_TYPE, GL_SECONDARY_COLOR_ARRAY_STRIDE,
      GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 0 },
    { GL_FOG_COORD_ARRAY, GL_FOG_COORD_ARRAY_POINTER, 0, GL_FOG_COORD_ARRAY_TYPE,
      GL_FOG_COORD_ARRAY_STRIDE, GL_FOG_COORD_ARRAY_BUFFER_BINDING, 1 },
    { GL_INDEX_ARRAY, GL_INDEX_ARRAY_POINTER, 0, GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE,
      GL_INDEX_ARRAY_BUFFER_BINDING, 1 },
    { GL_EDGE_FLAG_ARRAY, GL_EDGE_FLAG_ARRAY_POINTER, 0, 0, GL_EDGE_FLAG_ARRAY_STRIDE,
      GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1 },
    { GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_SIZE,
      GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
      GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 0 },
};

static int array_fits(const struct client_array *c, long long max_index)
{
    void *pointer = NULL;
    long long size, type, stride, element;
    if (!glIsEnabled(c->cap) || get_int(c->binding) != 0)
        return 1; /* off, or in a buffer object: the library checks offsets itself */
    glGetPointerv(c->pointer, &pointer);
    if (!pointer)
        return 1; /* documented: GL_INVALID_OPERATION, nothing read */
    if (!in_array_arena(pointer))
        return 0;
    size = c->fixed_size ? c->fixed_size : get_int(c->size);
    type = c->type ? type_bytes((GLenum)get_int(c->type)) : 1;
    stride = get_int(c->stride);
    if (type < 0 || size < 1 || stride < 0)
        return 0;
    element = size * type;
    return (unsigned char *)pointer + max_index * (stride ? stride : element) + element <=
           array_arena.base + array_arena.bytes;
}

/* Whether a draw reaching element max_index reads only the arena (queries that fail, as
 * between glBegin and glEnd, say no). */
static int arrays_fit(long long max_index)
{
    size_t i;
    int ok = 1, unit, units;
    GLint active;
    if (max_index < 0)
        return 1;
    glGetError();
    /* Between glBegin and glEnd every query fails, glGetError too (it returns 0): a query
     * that leaves its -1 in place says so. */
    units = -1;
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    if (units < 1)
        return 0;
    active = get_int(GL_CLIENT_ACTIVE_TEXTURE);
    for (i = 0; i + 1 < sizeof CLIENT_ARRAYS / sizeof CLIENT_ARRAYS[0]; i++)
        ok &= array_fits(&CLIENT_ARRAYS[i], max_index);
    for (unit = 0; unit < units && unit < 32; unit++) {
        glClientActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        ok &= array_fits(&CLIENT_ARRAYS[i], max_index);
    }
    glClientActiveTexture((GLenum)active);
    return glGetError() == GL_NO_ERROR && ok;
}

/* The largest index `count` indices of `type` at `indices` (or the element buffer) hold. */
static long long max_element(GLsizei count, GLenum type, const void *indices)
{
    long long size = type_bytes(type), i, max = -1;
    const unsigned char *p = indices;
    unsigned char *copy = NULL;
    GLint buffer = get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING);
    if (count <= 0 || (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT))
        return -1;
    if (buffer) {
        GLint bytes = 0;
        glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_SIZE, &bytes);
        copy = calloc((size_t)bytes + 4, 1);
        glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, bytes, copy);
        p = copy;
        count = (GLsizei)(bytes / size); /* the whole store: an upper bound */
    }
    for (i = 0; p && i < count; i++) {
        long long v = type == GL_UNSIGNED_BYTE ? p[i]
                    : type == GL_UNSIGNED_SHORT ? ((const GLushort *)(const void *)p)[i]
                    : ((const GLuint *)(const void *)p)[i];
        if (v > max)
            max = v;
    }
    free(copy);
    return max;
}

/* ---- arguments ---- */
static const GLenum LIKELY_ENUMS[] = {
    GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_TRIANGLES, GL_QUADS, GL_POLYGON, GL_LIGHT0, GL_LIGHT7,
    GL_POSITION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_SPOT_DIRECTION, GL_SPOT_CUTOFF,
    GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_SHININESS, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE,
    GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_PROXY_TEXTURE_2D,
    GL_RGBA, GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_COLOR_INDEX, GL_DEPTH_COMPONENT, GL_BGRA,
    GL_FLOAT, GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_INT, GL_SHORT, GL_BYTE,
    GL_DOUBLE, GL_BITMAP, GL_UNSIGNED_SHORT_5_6_5, GL_COMPILE, GL_COMPILE_AND_EXECUTE,
    GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE, GL_COLOR, GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER,
    GL_STATIC_DRAW, GL_READ_WRITE, GL_BUFFER_SIZE, GL_LIGHTING, GL_NORMALIZE, GL_CULL_FACE,
    GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_FEEDBACK,
    GL_SELECT, GL_RENDER, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE, GL_2D, GL_V3F, GL_T4F_C4F_N3F_V4F,
    GL_C4UB_V3F, GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_4, GL_MAP2_TEXTURE_COORD_2, GL_MAP1_COLOR_4,
    GL_COEFF, GL_ORDER, GL_DOMAIN, GL_FILL, GL_LINE, GL_POINT, GL_S, GL_T, GL_R, GL_Q,
    GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR, GL_EYE_PLANE, GL_SPHERE_MAP, GL_TEXTURE_ENV,
    GL_TEXTURE_ENV_MODE, GL_TEXTURE_MIN_FILTER, GL_TEXTURE_BORDER_COLOR, GL_TEXTURE0,
    GL_TEXTURE1, GL_TEXTURE7, GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_PIXEL_MAP_I_TO_I,
    GL_PIXEL_MAP_R_TO_R, GL_UNPACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
    GL_PACK_SKIP_IMAGES, GL_UNPACK_IMAGE_HEIGHT, GL_COLOR_TABLE, GL_CONVOLUTION_1D,
    GL_CONVOLUTION_2D, GL_SEPARABLE_2D, GL_HISTOGRAM, GL_MINMAX, GL_COLOR_TABLE_WIDTH,
    GL_SAMPLES_PASSED, GL_QUERY_RESULT, GL_CURRENT_QUERY, GL_MODELVIEW_MATRIX, GL_VIEWPORT,
    GL_CURRENT_COLOR, GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_TWO_SIDE, GL_FOG_COLOR, GL_FOG_MODE,
    GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SIZE_MIN, GL_COMPRESSED_TEXTURE_FORMATS,
    GL_FEEDBACK_BUFFER_POINTER, GL_SELECTION_BUFFER_POINTER, GL_VERTEX_ARRAY_POINTER,
    GL_BUFFER_MAP_POINTER, GL_2_BYTES, GL_3_BYTES, GL_4_BYTES, GL_EXTENSIONS, GL_VERSION,
    GL_AUTO_NORMAL, GL_TEXTURE_WIDTH, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
};

/* No GL enum has these values. */
static const GLenum BAD_ENUMS[] = { 0x7FFF0000u, 0xFFFFFFFFu, 0x9FFFu };

static int is_gl_enum(GLenum v)
{
    size_t lo = 0, hi = SWEEP_ENUM_COUNT;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (SWEEP_ENUMS[mid] == v)
            return 1;
        if (SWEEP_ENUMS[mid] < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return 0;
}

static long long pick_integer(void)
{
    static const long long values[] = { 0, 1, 2, 3, 4, 5, 8, 16, 30, 31, 32, 64, 255, 1000,
                                        -1, -2, -1000, INT_MAX, INT_MIN, 65536, 1 << 30, 100000 };
    if (below(3) == 0)
        return (long long)below(6);
    return values[below(sizeof values / sizeof values[0])];
}

static void pick_argument(const struct sweep_param *p, union sweep_arg *a)
{
    unsigned r;
    switch (p->kind) {
    case SWEEP_ENUM:
        r = below(20);
        if (r < 9)
            a->i = LIKELY_ENUMS[below(sizeof LIKELY_ENUMS / sizeof LIKELY_ENUMS[0])];
        else if (r < 16)
            a->i = SWEEP_ENUMS[below(SWEEP_ENUM_COUNT)];
        else if (r < 18)
            a->i = BAD_ENUMS[below(3)];
        else
            a->i = below(4);
        break;
    case SWEEP_BOOLEAN: {
        static const long long values[] = { 0, 1, 2, 255 };
        a->i = values[below(4)];
        break;
    }
    case SWEEP_BITFIELD: {
        static const long long values[] = { 0, 0xFFFFFFFFll, 0x000FFFFF, 0x4000, 0x100, 0x4500, 1, 2, 0x1FFFF, 0x80000000ll };
        a->i = below(5) == 0 ? (long long)(unsigned)next_u64() : values[below(10)];
        break;
    }
    case SWEEP_INTEGER:
    case SWEEP_SIZE:
        a->i = pick_integer();
        break;
    case SWEEP_POINTER_SIZED: {
        static const long long values[] = { 0, 1, 4, 16, 64, 1000, 4096, -1, -16, PTRDIFF_MAX, PTRDIFF_MIN, 1ll << 30, 1ll << 40 };
        a->i = values[below(sizeof values / sizeof values[0])];
        break;
    }
    case SWEEP_REAL: {
        static const double values[] = { 0.0, 1.0, -1.0, 0.5, 2.0, 10.0, -10.0, 45.0, 128.0, 1e30,
                                         -1e30, 1e-40, 1e300, -1e300, DBL_MAX, 1e6, -0.0 };
        r = below(10);
        if (r == 0)
            a->f = NAN;
        else if (r == 1)
            a->f = below(2) ? INFINITY : -INFINITY;
        else
            a->f = values[below(sizeof values / sizeof values[0])];
        break;
    }
    default:
        a->p = NULL;
        break;
    }
}

/* Fills pointer parameter k of fn by its rule: NULL, or a buffer of the allowed extent. */
static int give_pointer(int fn, union sweep_arg *a, int k)
{
    const struct sweep_param *p = &SWEEP_FUNCTIONS[fn].params[k];
    long long rule;
    int output = !p->constant;
    int fill = 0;
    a[k].p = NULL;
    slots[k].data = NULL;
    if (below(8) == 0)
        return 0;
    rule = pointer_rule(fn, a, k);
    switch (rule) {
    case NO_RULE:
        return -1;
    case ARRAY_POINTER: {
        GLint buffer = get_int(GL_ARRAY_BUFFER_BINDING);
        glGetError();
        if (buffer && below(2))
            a[k].p = (void *)(uintptr_t)(below(4) * 4); /* an offset into the buffer */
        else
            a[k].p = array_arena.base + below(64) * 4;
        return 0;
    }
    case FEEDBACK_POINTER:
    case SELECT_POINTER: {
        struct region *r = rule == FEEDBACK_POINTER ? &feedback_arena : &select_arena;
        long long size = (GLsizei)a[0].i;
        if (size >= 0 && size <= FEEDBACK_CAPACITY)
            a[k].p = r->base + r->bytes - (size_t)size * 4;
        return 0;
    }
    case CONTEXT_POINTER:
        if (context_count && below(3))
            a[k].p = contexts[below((unsigned)context_count)];
        else if (below(2))
            a[k].p = main_context;
        return 0;
    case INDEX_POINTERS: {
        /* primcount pointers, each to count[i] indices of the type at the arena's end. */
        long long primcount = (GLsizei)a[4].i, i, size = type_bytes((GLenum)a[2].i);
        const GLsizei *counts = a[1].p;
        void **pointers;
        if (primcount <= 0 || primcount > 4096)
            return 0;
        pointers = slot_buffer(k, (size_t)primcount * sizeof(void *), sizeof(void *), 0, 0);
        for (i = 0; i < primcount; i++) {
            long long bytes = counts && size > 0 && counts[i] > 0 ? counts[i] * size : 0;
            pointers[i] = bytes <= INDEX_ARENA_BYTES ? index_arena.base + index_arena.bytes - bytes : NULL;
        }
        a[k].p = pointers;
        return 0;
    }
    case ELEMENT_INDICES: {
        /* glDrawElements(mode, count, type, indices), glDrawRangeElements(mode, start, end,
         * count, type, indices): an offset into the element buffer when one is bound,
         * else count small indices of the type. */
        int at = k - 2;
        long long size = type_bytes((GLenum)a[at + 1].i), count = (GLsizei)a[at].i;
        GLint buffer = get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING);
        glGetError();
        if (buffer) {
            a[k].p = (void *)(uintptr_t)(below(4) * 4);
            return 0;
        }
        if (size <= 0 || count < 0)
            count = size = 0;
        if (count * size > SLOT_BYTES)
            return 0;
        a[k].p = slot_buffer(k, (size_t)(count * size), (size_t)size, 0, 1);
        return 0;
    }
    default:
        break;
    }
    if (rule < 0)
        rule = 0; /* an invalid format or a negative size: the call must fail and touch nothing */
    if (rule > SLOT_BYTES)
        return 0;
    if (same(SWEEP_FUNCTIONS[fn].name, "glCallLists") || same(SWEEP_FUNCTIONS[fn].name, "glMultiDrawArrays") ||
        (same(SWEEP_FUNCTIONS[fn].name, "glMultiDrawElements") && k == 1) ||
        starts(SWEEP_FUNCTIONS[fn].name, "glDelete"))
        fill = 1;
    if (pname_query(SWEEP_FUNCTIONS[fn].name) && pname_index(fn) >= 0)
        /* Canaries after the pname's values, up to the most any pname takes: a write past
         * the count is reported with the pname rather than as a fault. */
        a[k].p = slot_buffer_room(k, (size_t)rule,
                                  (size_t)pname_query(SWEEP_FUNCTIONS[fn].name)->room * p->size,
                                  p->size, output, fill);
    else
        a[k].p = slot_buffer(k, (size_t)rule, p->size, output, fill);
    return 0;
}

/* ---- the rules' tables ---- */

/* §2.6.3: the commands allowed between glBegin and glEnd. */
static int allowed_in_begin_end(const char *name)
{
    static const char *const attributes[] = {
        "glVertex", "glColor", "glSecondaryColor", "glNormal", "glTexCoord", "glMultiTexCoord",
        "glIndex", "glFogCoord", "glEdgeFlag", "glEvalCoord",
    };
    static const char *const suffixes[] = { "b", "s", "i", "f", "d", "ub", "us", "ui", "x", "" };
    size_t i, j;
    for (i = 0; i < sizeof attributes / sizeof attributes[0]; i++) {
        const char *rest;
        if (!starts(name, attributes[i]))
            continue;
        rest = name + strlen(attributes[i]);
        if (*rest >= '1' && *rest <= '4')
            rest++;
        for (j = 0; j < sizeof suffixes / sizeof suffixes[0]; j++) {
            size_t n = strlen(suffixes[j]);
            if (strncmp(rest, suffixes[j], n) == 0 && (same(rest + n, "") || same(rest + n, "v")))
                return 1;
        }
    }
    return starts(name, "glMaterial") || starts(name, "glEvalPoint") || same(name, "glArrayElement") ||
           same(name, "glCallList") || same(name, "glCallLists") || same(name, "glEnd");
}

/* Not GL commands: no begin/end or display list rule (the context functions). */
static int outside_gl_rules(const char *name)
{
    return same(name, "fflCreateContext") || same(name, "fflMakeCurrent") ||
           same(name, "fflDestroyContext") || same(name, "fflGetCurrentContext") ||
           same(name, "fflSetThreads") || same(name, "fflGetThreads") || same(name, "glGetError") ||
           /* reading what capture collected is allowed anywhere (include/fflight.h) */
           same(name, "fflCaptureVertexCount") || same(name, "fflCapturePrimitiveCount") ||
           same(name, "fflCaptureReadVertices") || same(name, "fflCaptureReadPrimitives") ||
           same(name, "fflCaptureReadTexCoords");
}

/* §2.6.3: client-state commands are not allowed between glBegin and glEnd, "but an error
 * may or may not be generated" (fflight must only not crash). */
static int client_state_command(const char *name)
{
    return same(name, "glEnableClientState") || same(name, "glDisableClientState") ||
           same(name, "glPushClientAttrib") || same(name, "glPopClientAttrib") ||
           same(name, "glInterleavedArrays") || same(name, "glClientActiveTexture") ||
           starts(name, "glPixelStore") || (strstr(name, "Pointer") && !starts(name, "glGet"));
}

/* §5.4: commands executed at once, never compiled (and fflight's own functions). */
static int executed_immediately(const char *name, const union sweep_arg *a)
{
    static const char *const names[] = {
        "glIsList", "glGenLists", "glDeleteLists", "glFeedbackBuffer", "glSelectBuffer",
        "glRenderMode", "glClientActiveTexture", "glInterleavedArrays", "glEnableClientState",
        "glDisableClientState", "glPushClientAttrib", "glPopClientAttrib", "glReadPixels",
        "glGenTextures", "glDeleteTextures", "glAreTexturesResident", "glIsTexture",
        "glGenQueries", "glDeleteQueries", "glIsQuery", "glBindBuffer", "glDeleteBuffers",
        "glGenBuffers", "glIsBuffer", "glBufferData", "glBufferSubData", "glMapBuffer",
        "glUnmapBuffer", "glFlush", "glFinish", "glIsEnabled", "glGetError",
    };
    size_t i;
    GLenum target = (GLenum)a[0].i;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (same(name, names[i]))
            return 1;
    if (starts(name, "ffl") || starts(name, "glGet") || starts(name, "glPixelStore") ||
        (strstr(name, "Pointer") && !starts(name, "glGet")))
        return 1;
    /* Proxy targets are executed immediately. */
    if (starts(name, "glTexImage"))
        return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D ||
               target == GL_PROXY_TEXTURE_3D || target == GL_PROXY_TEXTURE_CUBE_MAP;
    if (same(name, "glColorTable"))
        return target == GL_PROXY_COLOR_TABLE || target == GL_PROXY_POST_CONVOLUTION_COLOR_TABLE ||
               target == GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE;
    if (same(name, "glHistogram"))
        return target == GL_PROXY_HISTOGRAM;
    return 0;
}

static int error_index(GLenum e)
{
    switch (e) {
    case GL_NO_ERROR: return 0;
    case GL_INVALID_ENUM: return 1;
    case GL_INVALID_VALUE: return 2;
    case GL_INVALID_OPERATION: return 3;
    case GL_STACK_OVERFLOW: case GL_STACK_UNDERFLOW: return 4;
    case GL_OUT_OF_MEMORY: return 5;
    case GL_TABLE_TOO_LARGE: return 6;
    default: return 7;
    }
}

static int is_error_code(GLenum e)
{
    return e == GL_NO_ERROR || e == GL_INVALID_ENUM || e == GL_INVALID_VALUE ||
           e == GL_INVALID_OPERATION || e == GL_STACK_OVERFLOW || e == GL_STACK_UNDERFLOW ||
           e == GL_OUT_OF_MEMORY || e == GL_TABLE_TOO_LARGE;
}

/* ---- one call ---- */
enum situation { OUTSIDE, BEGIN_END, COMPILE, COMPILE_AND_EXECUTE, RANDOM, SITUATIONS };
static const char *const SITUATION_NAMES[] = { "outside", "between glBegin and glEnd",
                                                "compiling a GL_COMPILE list",
                                                "compiling a GL_COMPILE_AND_EXECUTE list",
                                                "random sequence" };
#define SWEEP_LIST 4242

static long long called[SWEEP_FUNCTION_COUNT][SITUATIONS];
static long long skipped_draws, skipped_work, errors_seen[8];
static int no_rule_reported[SWEEP_FUNCTION_COUNT];

static void drain_errors(void)
{
    int n;
    for (n = 0; n < 16 && glGetError() != GL_NO_ERROR; n++)
        ;
}

/* Back to the main context, outside glBegin/glEnd and list compilation. */
static void reset(void)
{
    fflMakeCurrent(NULL);
    glEnd();
    glEndList();
    drain_errors();
}

static long long draw_max_index(int fn, const union sweep_arg *a)
{
    const char *name = SWEEP_FUNCTIONS[fn].name;
    if (same(name, "glArrayElement"))
        return (GLint)a[0].i;
    if (same(name, "glDrawArrays")) {
        long long first = (GLint)a[1].i, count = (GLsizei)a[2].i;
        return first < 0 || count <= 0 ? -1 : first + count - 1;
    }
    if (same(name, "glDrawElements"))
        return max_element((GLsizei)a[1].i, (GLenum)a[2].i, a[3].p);
    if (same(name, "glDrawRangeElements"))
        return max_element((GLsizei)a[3].i, (GLenum)a[4].i, a[5].p);
    if (same(name, "glMultiDrawArrays")) {
        const GLint *first = a[1].p;
        const GLsizei *count = a[2].p;
        long long i, max = -1, n = (GLsizei)a[3].i;
        for (i = 0; first && count && i < n; i++)
            if (first[i] >= 0 && count[i] > 0 && first[i] + (long long)count[i] - 1 > max)
                max = first[i] + (long long)count[i] - 1;
        return max;
    }
    if (same(name, "glMultiDrawElements")) {
        const GLsizei *count = a[1].p;
        void *const *indices = a[3].p;
        long long i, max = -1, n = (GLsizei)a[4].i;
        for (i = 0; count && indices && i < n; i++) {
            long long m = max_element(count[i], (GLenum)a[2].i, indices[i]);
            if (m > max)
                max = m;
        }
        return max;
    }
    return -2; /* not a draw */
}

/* Evaluator meshes do the work their ranges ask for (2^62 vertices is GL's right answer to
 * a range of 2^31 by 2^31): the sweep makes those of at most a million vertices. */
static int unbounded_work(const char *name, const union sweep_arg *a)
{
    double i = (double)(GLint)a[2].i - (double)(GLint)a[1].i + 1;
    double j = (double)(GLint)a[4].i - (double)(GLint)a[3].i + 1;
    if (same(name, "glEvalMesh1"))
        return i > 1e6;
    if (same(name, "glEvalMesh2"))
        return i > 0 && j > 0 && i * j > 1e6;
    return 0;
}

/* Prepares arguments; 0 when the call may be made. */
static int prepare(int fn, union sweep_arg *a)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    int k;
    long long max_index;
    for (k = 0; k < f->count; k++)
        pick_argument(&f->params[k], &a[k]);
    for (k = 0; k < f->count; k++) {
        slots[k].data = NULL;
        if (f->params[k].kind != SWEEP_POINTER && f->params[k].kind != SWEEP_POINTER_ARRAY)
            continue;
        if (give_pointer(fn, a, k) != 0) {
            if (!no_rule_reported[fn]) {
                char what[200];
                no_rule_reported[fn] = 1;
                snprintf(what, sizeof what, "no rule for how much %s may touch through %s",
                         f->name, f->params[k].name);
                current_fn = -1;
                fail("coverage", what);
            }
            return -1;
        }
        if (slots[k].data && a[k].p == slots[k].data)
            slot_save(k);
    }
    if (unbounded_work(f->name, a)) {
        skipped_work++;
        return -1;
    }
    max_index = draw_max_index(fn, a);
    if (max_index > -2 && !arrays_fit(max_index)) {
        skipped_draws++;
        return -1;
    }
    drain_errors();
    return 0;
}

static void check_string(const GLubyte *s)
{
    if (s && strlen((const char *)s) > 100000)
        fail("R6", "glGetString's string is not terminated within 100000 bytes");
}

/* How many elements of `size` bytes a call wrote at `data` (the last one not all canary). */
static int written_elements(const unsigned char *data, int capacity, size_t size)
{
    int n;
    size_t b;
    for (n = capacity; n > 0; n--)
        for (b = 0; b < size; b++)
            if (data[(size_t)(n - 1) * size + b] != CANARY)
                return n;
    return 0;
}

/* R2 for the glGet*v family: the five forms must write the same number of values for the
 * same pname, each into a buffer of 16 against the guard page (R7 checks that number
 * against the state tables). */
static long long get_forms_compared;
static void check_get_forms(GLenum pname)
{
    int counts[5], k;
    char what[160];
    for (k = 0; k < 5; k++) {
        static const size_t sizes[5] = { sizeof(GLboolean), sizeof(GLint), sizeof(GLfloat),
                                         sizeof(GLdouble), sizeof(GLfixed) };
        unsigned char *p = slot_buffer(MAX_PARAMS, 16 * sizes[k], sizes[k], 1, 0);
        switch (k) {
        case 0: glGetBooleanv(pname, (GLboolean *)(void *)p); break;
        case 1: glGetIntegerv(pname, (GLint *)(void *)p); break;
        case 2: glGetFloatv(pname, (GLfloat *)(void *)p); break;
        case 3: glGetDoublev(pname, (GLdouble *)(void *)p); break;
        default: glGetFixedv(pname, (GLfixed *)(void *)p); break;
        }
        counts[k] = glGetError() == GL_NO_ERROR ? written_elements(p, 16, sizes[k]) : -1;
    }
    get_forms_compared += counts[0] >= 0;
    for (k = 1; k < 5; k++)
        if (counts[k] != counts[0]) {
            snprintf(what, sizeof what,
                     "pname 0x%x: glGetBooleanv wrote %d values, Integerv %d, Floatv %d, Doublev %d, "
                     "Fixedv %d", pname, counts[0], counts[1], counts[2], counts[3], counts[4]);
            fail("R2", what);
            return;
        }
}

/* R7 for every pname-taking query and every enum of the header as its pname, in the
 * initial state (a buffer bound, a query object ended): a pname the query accepts is in
 * its table and the query writes exactly the table's count, canaries after it up to the
 * most any pname takes; one it refuses writes nothing. */
static long long pnames_checked;
static int pname_functions;
/* Query fn with first argument `target` and every pname: the header's enums, then the
 * table's pnames the header has no name for. */
static void check_pname_target(int fn, const struct pname_query *q, GLenum target)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    int at = pname_index(fn), out = f->count - 1;
    size_t e = f->params[out].size, i;
    for (i = 0; i < SWEEP_ENUM_COUNT + q->size; i++) {
        union sweep_arg a[MAX_PARAMS], ret;
        GLenum pname = i < SWEEP_ENUM_COUNT ? SWEEP_ENUMS[i] : q->table[i - SWEEP_ENUM_COUNT].pname;
        int count = pname_count(q, pname), written;
        GLenum error;
        char what[200];
        if (i >= SWEEP_ENUM_COUNT && is_gl_enum(pname))
            continue;
        drain_errors();
        memset(a, 0, sizeof a);
        a[0].i = target;
        a[at].i = pname;
        a[out].p = slot_buffer_room(MAX_PARAMS, count < 0 ? 0 : (size_t)count * e,
                                    (size_t)q->room * e, e, 1, 0);
        current_fn = fn;
        memcpy(current_args, a, sizeof a);
        current_situation = "every pname";
        f->call(a, &ret);
        error = glGetError();
        written = written_elements(a[out].p, q->room, e);
        pnames_checked += error == GL_NO_ERROR;
        if (error == GL_NO_ERROR && count == PNAME_UNKNOWN)
            snprintf(what, sizeof what, "accepted pname 0x%x, which tests/sweep/pname_counts.h lacks",
                     pname);
        else if (written != (error == GL_NO_ERROR ? count : 0))
            snprintf(what, sizeof what, "pname 0x%x: %s %d values, the state tables give %d", pname,
                     error == GL_NO_ERROR ? "wrote" : "failed and wrote", written,
                     error == GL_NO_ERROR ? count : 0);
        else
            continue;
        printf("R7 %s(0x%x, 0x%x): %s\n", f->name, target, pname, what);
        fail("R7", what);
    }
}

static void check_pname_counts(void)
{
    GLuint buffer = 0, query = 0;
    int fn;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glEndQuery(GL_SAMPLES_PASSED);
    drain_errors();
    for (fn = 0; fn < SWEEP_FUNCTION_COUNT; fn++) {
        const struct pname_query *q = pname_query(SWEEP_FUNCTIONS[fn].name);
        int t;
        if (!q || pname_index(fn) < 0)
            continue;
        pname_functions++;
        for (t = 0; t == 0 || (t < 4 && q->targets[t]); t++)
            check_pname_target(fn, q, same(q->prefix, "glGetQueryObject") ? query : q->targets[t]);
    }
    current_fn = -1;
    glDeleteQueries(1, &query);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &buffer);
    drain_errors();
}

/* The commands setting a pname's values, in a context of their own. Each pname of their
 * tables with exactly its count of (hostile) values against the guard page: a read past the
 * count faults; the const buffer must stay unchanged (R2). Each enum of the header their
 * table lacks, scalar forms too: refused with an error, reading nothing (a pointer form's
 * buffer has no value before the guard page). */
static long long pname_reads_checked, unlisted_pnames_refused;
static int pname_setter_functions;

/* Setter fn (first argument `target`, pname argument `at`) with each pname of its table. */
static void check_setter_reads(int fn, const struct pname_query *q, GLenum target, int at)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    int in = f->count - 1;
    size_t e = f->params[in].size, i;
    for (i = 0; i < q->size; i++) {
        union sweep_arg a[MAX_PARAMS], ret;
        GLenum error;
        drain_errors();
        memset(a, 0, sizeof a);
        a[0].i = target;
        a[at].i = q->table[i].pname;
        a[in].p = slot_buffer(MAX_PARAMS, (size_t)q->table[i].count * e, e, 0, 0);
        slot_save(MAX_PARAMS);
        current_fn = fn;
        memcpy(current_args, a, sizeof a);
        current_situation = "every pname";
        f->call(a, &ret);
        error = glGetError();
        slot_check(MAX_PARAMS, error != GL_NO_ERROR, "params");
        pname_reads_checked++;
    }
}

/* Setter fn with each enum of the header its table lacks. */
static void check_setter_refusals(int fn, const struct pname_query *q, GLenum target, int at)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    int in = f->count - 1;
    size_t i;
    for (i = 0; i < SWEEP_ENUM_COUNT; i++) {
        union sweep_arg a[MAX_PARAMS], ret;
        GLenum pname = SWEEP_ENUMS[i];
        char what[200];
        if (pname_count(q, pname) != PNAME_UNKNOWN)
            continue;
        drain_errors();
        memset(a, 0, sizeof a);
        a[0].i = target;
        a[at].i = pname;
        if (f->params[in].kind == SWEEP_POINTER)
            a[in].p = slot_buffer(MAX_PARAMS, 0, f->params[in].size, 0, 0);
        current_fn = fn;
        memcpy(current_args, a, sizeof a);
        current_situation = "unlisted pname";
        f->call(a, &ret);
        if (glGetError() != GL_NO_ERROR) {
            unlisted_pnames_refused++;
            continue;
        }
        snprintf(what, sizeof what, "accepted pname 0x%x, which its table lacks", pname);
        printf("R7 %s(0x%x, 0x%x): %s\n", f->name, target, pname, what);
        fail("R7", what);
    }
}

static void check_setter_pnames(void)
{
    FflContext *context = fflCreateContext();
    int fn, t;
    fflMakeCurrent(context);
    for (fn = 0; fn < SWEEP_FUNCTION_COUNT; fn++) {
        const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
        const struct pname_query *q = pname_setter(f->name);
        int at = pname_index(fn), pointer = f->params[f->count - 1].kind == SWEEP_POINTER;
        if (!q || at < 0)
            continue;
        pname_setter_functions += pointer;
        for (t = 0; t == 0 || (t < 4 && q->targets[t]); t++) {
            if (pointer)
                check_setter_reads(fn, q, q->targets[t], at);
            check_setter_refusals(fn, q, q->targets[t], at);
        }
    }
    current_fn = -1;
    fflMakeCurrent(main_context);
    fflDestroyContext(context);
}

/* Makes the call in `situation`, checks the rules; returns the error it raised. */
static GLenum make_call(int fn, enum situation situation)
{
    const struct sweep_function *f = &SWEEP_FUNCTIONS[fn];
    union sweep_arg a[MAX_PARAMS], ret;
    GLenum error, list_error = GL_NO_ERROR;
    int k, bad_enum = 0, negative_size = 0, null_pointer = 0;
    char what[200];
    memset(a, 0, sizeof a);
    if (prepare(fn, a) != 0)
        return GL_NO_ERROR;
    for (k = 0; k < f->count; k++) {
        if (f->params[k].kind == SWEEP_ENUM && !is_gl_enum((GLenum)a[k].i))
            bad_enum = 1;
        if (f->params[k].kind == SWEEP_SIZE && (GLsizei)a[k].i < 0)
            negative_size = 1;
        if ((f->params[k].kind == SWEEP_POINTER || f->params[k].kind == SWEEP_POINTER_ARRAY) && !a[k].p)
            null_pointer = 1;
    }
    if (situation == BEGIN_END)
        glBegin(GL_POINTS + below(10));
    else if (situation == COMPILE)
        glNewList(SWEEP_LIST, GL_COMPILE);
    else if (situation == COMPILE_AND_EXECUTE)
        glNewList(SWEEP_LIST, GL_COMPILE_AND_EXECUTE);
    if (situation != BEGIN_END)
        drain_errors(); /* glGetError is GL_INVALID_OPERATION between glBegin and glEnd */
    current_fn = fn;
    memcpy(current_args, a, sizeof a);
    current_situation = SITUATION_NAMES[situation];
    ret.p = NULL;
    alarm(call_seconds);
    f->call(a, &ret);
    alarm(0);
    calls_made++;
    called[fn][situation]++;
    if (situation == BEGIN_END)
        glEnd();
    error = glGetError();
    if (situation == BEGIN_END) {
    } else if (situation == COMPILE || situation == COMPILE_AND_EXECUTE) {
        glEndList();
        if (situation == COMPILE) {
            drain_errors();
            glCallList(SWEEP_LIST);
            list_error = glGetError();
        }
    }
    errors_seen[error_index(error)]++;
    if (!is_error_code(error)) {
        snprintf(what, sizeof what, "glGetError returned 0x%x", error);
        fail("R1", what);
    }
    if (!is_error_code(list_error)) {
        snprintf(what, sizeof what, "glGetError returned 0x%x after glCallList", list_error);
        fail("R1", what);
    }
    for (k = 0; k < f->count; k++)
        if (slots[k].data && a[k].p == slots[k].data)
            slot_check(k, error != GL_NO_ERROR && situation != RANDOM, f->params[k].name);
    /* A NULL pointer is no GL argument (fflight's GL_INVALID_VALUE may come first). */
    if (situation == BEGIN_END && !allowed_in_begin_end(f->name) && !outside_gl_rules(f->name) &&
        !client_state_command(f->name) && error != GL_INVALID_OPERATION &&
        !(null_pointer && error != GL_NO_ERROR)) {
        snprintf(what, sizeof what, "0x%x between glBegin and glEnd, not GL_INVALID_OPERATION", error);
        fail("R3", what);
    }
    if (situation == OUTSIDE && (bad_enum || negative_size) && error == GL_NO_ERROR &&
        !outside_gl_rules(f->name)) {
        fail("R4", bad_enum ? "no error for an enum no GL enum has" : "no error for a negative GLsizei");
    }
    if (situation == COMPILE && same(f->name, "glNewList") && error == GL_NO_ERROR)
        fail("R5", "glNewList while compiling a list raised no error");
    if (situation == COMPILE && !executed_immediately(f->name, a) && !starts(f->name, "glMultiDraw") &&
        !same(f->name, "glNewList") && error != GL_NO_ERROR) {
        snprintf(what, sizeof what, "0x%x while compiling a command §5.4 compiles", error);
        fail("R5", what);
    }
    if ((situation == OUTSIDE || situation == RANDOM) && error == GL_NO_ERROR &&
        (same(f->name, "glGetBooleanv") || same(f->name, "glGetIntegerv") ||
         same(f->name, "glGetFloatv") || same(f->name, "glGetDoublev") || same(f->name, "glGetFixedv")))
        check_get_forms((GLenum)a[0].i);
    /* (Not in the random sequence: there glGetError may run between glBegin and glEnd, or
     * without a context, and return GL_NO_ERROR for a call that failed.) */
    if (error == GL_NO_ERROR && situation != RANDOM && pname_query(f->name) && pname_index(fn) >= 0 &&
        pname_count(pname_query(f->name), (GLenum)a[pname_index(fn)].i) == PNAME_UNKNOWN) {
        snprintf(what, sizeof what, "accepted pname 0x%x, which tests/sweep/pname_counts.h lacks",
                 (GLenum)a[pname_index(fn)].i);
        fail("R7", what);
    }
    if (same(f->name, "glGetString"))
        check_string(ret.p);
    if (same(f->name, "fflCreateContext"))
        remember_context(ret.p);
    if (same(f->name, "fflDestroyContext") && ret.i == GL_TRUE)
        forget_context(a[0].p);
    if (same(f->name, "glMapBuffer") && ret.p) {
        GLint size = 0;
        unsigned sum = 0;
        GLint i;
        glGetBufferParameteriv((GLenum)a[0].i, GL_BUFFER_SIZE, &size);
        for (i = 0; i < size; i++)
            sum += ((volatile unsigned char *)ret.p)[i];
        (void)sum;
    }
    current_fn = -1;
    return error;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static long env_long(const char *name, long fallback)
{
    const char *v = getenv(name);
    return v && *v ? strtol(v, NULL, 10) : fallback;
}

int main(void)
{
    long rounds = env_long("SWEEP_ROUNDS", 12);
    double seconds = (double)env_long("SWEEP_SECONDS", 20);
    long max_calls = env_long("SWEEP_CALLS", 100000);
    int fn, covered = 0, s;
    long r;
    size_t i;
    double start;
    rng_state = (unsigned long long)env_long("SWEEP_SEED", 9);
    call_seconds = (unsigned)env_long("SWEEP_CALL_SECONDS", 10);
    signal(SIGALRM, on_signal);
    signal(SIGSEGV, on_signal);
    signal(SIGBUS, on_signal);
    signal(SIGFPE, on_signal);
    signal(SIGILL, on_signal);
    signal(SIGABRT, on_signal);

    array_arena = map_region(ARRAY_ARENA_BYTES);
    for (i = 0; i < array_arena.bytes; i++)
        array_arena.base[i] = (unsigned char)next_u64();
    feedback_arena = map_region(FEEDBACK_CAPACITY * 4);
    select_arena = map_region(FEEDBACK_CAPACITY * 4);
    index_arena = map_region(INDEX_ARENA_BYTES);
    for (i = 0; i < index_arena.bytes; i++)
        index_arena.base[i] = (unsigned char)(i % 2 == 0 ? below(6) : 0);
    glGetError();
    main_context = fflGetCurrentContext();
    if (!main_context) {
        printf("FAIL: no default context\n");
        return 1;
    }

    /* Every enum of the header as a glGet pname, through the five forms. */
    for (i = 0; i < SWEEP_ENUM_COUNT; i++)
        check_get_forms(SWEEP_ENUMS[i]);
    start = now();
    check_pname_counts();
    check_setter_pnames();
    printf("pnames: %lld accepted (query, target, pname) calls of %d queries write their state-table "
           "count; %lld (command, target, pname) calls of %d commands read no more than it, "
           "%lld with a pname their table lacks refused; in %.2f s\n",
           pnames_checked, pname_functions, pname_reads_checked, pname_setter_functions,
           unlisted_pnames_refused, now() - start);

    /* Every function, every situation, `rounds` argument draws each. */
    start = now();
    for (fn = 0; fn < SWEEP_FUNCTION_COUNT; fn++)
        for (s = OUTSIDE; s < RANDOM; s++)
            for (r = 0; r < rounds; r++) {
                make_call(fn, (enum situation)s);
                reset();
            }
    printf("situations: %ld rounds x %d situations x %d functions in %.1f s\n", rounds, RANDOM,
           SWEEP_FUNCTION_COUNT, now() - start);

    /* Random order, random arguments, no reset but every few hundred calls. */
    start = now();
    for (r = 0; r < max_calls && now() - start < seconds; r++) {
        make_call((int)below(SWEEP_FUNCTION_COUNT), RANDOM);
        if (r % 500 == 499)
            reset();
    }
    reset();
    printf("random: %ld calls in %.1f s\n", r, now() - start);

    for (fn = 0; fn < SWEEP_FUNCTION_COUNT; fn++) {
        int all = 1;
        for (s = OUTSIDE; s < RANDOM; s++)
            all &= called[fn][s] > 0;
        if (all)
            covered++;
        else
            printf("not called in every situation: %s\n", SWEEP_FUNCTIONS[fn].name);
    }
    printf("calls: %lld; skipped: %lld draws that would read outside the arrays given, %lld "
           "evaluator meshes of over a million vertices\n", calls_made, skipped_draws, skipped_work);
    printf("errors: none %lld, GL_INVALID_ENUM %lld, GL_INVALID_VALUE %lld, GL_INVALID_OPERATION %lld, "
           "stack %lld, GL_OUT_OF_MEMORY %lld, GL_TABLE_TOO_LARGE %lld\n",
           errors_seen[0], errors_seen[1], errors_seen[2], errors_seen[3], errors_seen[4],
           errors_seen[5], errors_seen[6]);
    {
        int forbidden = 0, client = 0, compiled = 0, pointers = 0;
        union sweep_arg zero[MAX_PARAMS];
        memset(zero, 0, sizeof zero);
        for (fn = 0; fn < SWEEP_FUNCTION_COUNT; fn++) {
            const char *name = SWEEP_FUNCTIONS[fn].name;
            int k;
            if (client_state_command(name))
                client++;
            else if (!allowed_in_begin_end(name) && !outside_gl_rules(name))
                forbidden++;
            if (!executed_immediately(name, zero))
                compiled++;
            for (k = 0; k < SWEEP_FUNCTIONS[fn].count; k++)
                pointers += SWEEP_FUNCTIONS[fn].params[k].kind >= SWEEP_POINTER;
        }
        printf("rules: R3 (GL_INVALID_OPERATION between glBegin/glEnd) for %d functions, %d client-state "
               "ones free; R5 (no error while compiled) for %d; %d pointer parameters guarded; "
               "the five glGet*v forms agree on %lld successful queries (every pname of the header)\n",
               forbidden, client, compiled, pointers, get_forms_compared);
    }
    printf("functions called: %d of %d in every situation\n", covered, SWEEP_FUNCTION_COUNT);
    while (context_count)
        fflDestroyContext(contexts[--context_count]);
    printf("%s: %d failures\n", failures ? "FAIL" : "PASS", failures);
    return failures ? 1 : 0;
}
