/*
 * legacy_ref.h - runs the display() of a program under examples/legacy/ in feedback mode
 * (GL_3D_COLOR_TEXTURE) and gives each fed-back vertex the texture coordinates the spec
 * gives it, for what OSMesa's feedback does not return (generated coordinates, the texture
 * matrix: docs/osmesa-differences.md, 6 and 19).
 *
 * A c_tests/legacy_*.c wrapper defines, before including the example,
 *     #define glBegin lref_begin
 *     #define glNormal3f lref_normal3f
 *     #define glVertex3f lref_vertex3f
 * (and glMultiTexCoord2f / glTexCoord2f as lref_multi_tex_coord2f / lref_tex_coord2f when
 * the example gives coordinates), so each glVertex3f is recorded with its reference
 * window position (vertex_ref.h) and the coordinates `lref.expected` computes for it from
 * the object position, the current normal and texture coordinates of unit 0 and the
 * modelview and texture matrix of unit 0 read at its glBegin (the state GL stored). Each
 * fed-back vertex found at a recorded vertex's position is printed with " ref strq ...":
 * its texture coordinates are checked against the reference. OSMesa computes them only
 * for a unit with texturing enabled and a complete texture; where a program's unit 0 is
 * not, `lref.reason` marks the line " osmesa-exempt=<reason>" (fflight is checked alone).
 * Include after ffl_test.h, gl_mirror.h, vertex_ref.h and texgen_ref.h.
 */
#ifndef FFL_LEGACY_REF_H
#define FFL_LEGACY_REF_H

#define LREF_BUF_SIZE 32768

/* The texture coordinates of unit 0 the spec gives a vertex at `object` (x, y, z, 1). */
typedef void (*lref_strq_fn)(const double *object, double *strq);

static struct {
    ref_state ref;
    vref_set vref;
    ffl_fb fb;
    GLfloat buf[LREF_BUF_SIZE];
    double strq[VREF_MAX_VERTICES][4];
    GLfloat normal[3];
    GLfloat tex_coord[4]; /* unit 0's current coordinates */
    double texture_matrix[16]; /* unit 0's */
    lref_strq_fn expected;
    const char *reason;
} lref;

/* glBegin: reads the modelview and unit 0's texture matrix first (queries are not allowed
 * between glBegin and glEnd) and marks the primitive for the feedback printer. */
static inline void lref_begin(GLenum mode)
{
    GLfloat f[16];
    GLint unit;
    int k;
    glGetFloatv(GL_MODELVIEW_MATRIX, f);
    for (k = 0; k < 16; k++)
        lref.ref.modelview.m[k] = f[k];
    glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
    glActiveTexture(GL_TEXTURE0);
    glGetFloatv(GL_TEXTURE_MATRIX, f);
    for (k = 0; k < 16; k++)
        lref.texture_matrix[k] = f[k];
    glActiveTexture((GLenum)unit);
    ffl_fb_mark(&lref.fb, mode);
    glBegin(mode);
}

static inline void lref_normal3f(GLfloat x, GLfloat y, GLfloat z)
{
    lref.normal[0] = x;
    lref.normal[1] = y;
    lref.normal[2] = z;
    glNormal3f(x, y, z);
    ref_normal3f(&lref.ref, x, y, z);
}

static inline void lref_tex_coord2f(GLfloat s, GLfloat t)
{
    lref.tex_coord[0] = s;
    lref.tex_coord[1] = t;
    lref.tex_coord[2] = 0.0f;
    lref.tex_coord[3] = 1.0f;
    glTexCoord2f(s, t);
}

static inline void lref_multi_tex_coord2f(GLenum unit, GLfloat s, GLfloat t)
{
    if (unit == GL_TEXTURE0) {
        lref.tex_coord[0] = s;
        lref.tex_coord[1] = t;
        lref.tex_coord[2] = 0.0f;
        lref.tex_coord[3] = 1.0f;
    }
    glMultiTexCoord2f(unit, s, t);
}

static inline void lref_vertex3f(GLfloat x, GLfloat y, GLfloat z)
{
    double object[4];
    object[0] = x;
    object[1] = y;
    object[2] = z;
    object[3] = 1.0;
    if (lref.vref.n < VREF_MAX_VERTICES)
        lref.expected(object, lref.strq[lref.vref.n]);
    vref_vertex3f(&lref.vref, x, y, z);
}

static inline void lref_note(void *user, GLenum mode, GLenum token, const GLfloat *vertices,
                             int nverts, int k, GLenum type)
{
    const GLfloat *fed = vertices + k * ffl_feedback_vertex_size(type);
    int index = vref_index_of(&lref.vref, fed, fed + 2);
    (void)user;
    (void)mode;
    (void)token;
    (void)nverts;
    if (index < 0) {
        lref.vref.clip_made++;
        printf(" clip-made");
        return;
    }
    lref.vref.matched++;
    if (lref.reason != NULL)
        printf(" osmesa-exempt=%s", lref.reason);
    printf(" ref");
    ffl_pdv("strq", lref.strq[index], 4);
}

/* Starts the reference: ref_init and the current coordinates' initial value. `reason`:
 * the osmesa-exempt mark of every line with a reference, or NULL. */
static inline void lref_init(lref_strq_fn expected, const char *reason)
{
    ref_init(&lref.ref);
    lref.expected = expected;
    lref.reason = reason;
    lref.tex_coord[0] = lref.tex_coord[1] = lref.tex_coord[2] = 0.0f;
    lref.tex_coord[3] = 1.0f;
}

/* One feedback pass of `display` (after the example's init and reshape), printed under
 * `tag` with the references. Returns nonzero on a feedback failure. */
static inline int lref_run(const char *tag, void (*display)(void))
{
    int failed;
    mirror_read_stored_state(&lref.ref);
    vref_start(&lref.vref, &lref.ref);
    ffl_fb_init(&lref.fb);
    ffl_fb_start(&lref.fb, lref.buf, LREF_BUF_SIZE, GL_3D_COLOR_TEXTURE);
    display();
    failed = ffl_fb_finish(&lref.fb, tag, lref_note, NULL);
    ffl_print_error(tag);
    return failed;
}

#endif /* FFL_LEGACY_REF_H */
