/* ffl-test: fflight-only */
/*
 * Every texture unit's coordinates travel with each vertex to capture (GL 1.3 multitexture):
 * units 0 to GL_MAX_TEXTURE_UNITS - 1 each get their own texture matrix and coordinate
 * generation (object linear, eye linear, sphere map, reflection map, normal map, none) and
 * their own coordinates, through immediate mode (glMultiTexCoord in several forms), vertex
 * arrays (a texture coordinate array per unit through glClientActiveTexture and
 * glTexCoordPointer, of different types, sizes and strides, one in a buffer object; units
 * without an array keep their current coordinates) drawn by glDrawArrays, glDrawElements,
 * glDrawRangeElements, glMultiDrawArrays and glArrayElement, and display lists compiling both
 * (replayed after the arrays and current coordinates changed). fflCaptureReadTexCoords
 * returns each unit's coordinates, checked against the double-precision evaluation of
 * §2.11.4 and the texture matrix in reference/texgen_ref.h. Feedback still reports unit 0's
 * (§5.3). Units beyond the limit are GL_INVALID_ENUM and change nothing.
 */
#include "ffl_test.h"
#include "reference/texgen_ref.h"

#define MAX_UNITS 8
#define VERTICES 24
#define TOLERANCE 2e-5

static int failures = 0;
static GLint units;

static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("FAILED %s\n", what);
        failures++;
    }
}

/* What each unit generates, per coordinate (0: nothing). */
static GLenum gen_mode(int unit, int coord)
{
    static const GLenum modes[8][4] = {
        { 0, 0, 0, 0 },
        { GL_OBJECT_LINEAR, GL_OBJECT_LINEAR, 0, 0 },
        { GL_EYE_LINEAR, 0, GL_EYE_LINEAR, GL_OBJECT_LINEAR },
        { GL_SPHERE_MAP, GL_SPHERE_MAP, 0, 0 },
        { GL_REFLECTION_MAP, GL_REFLECTION_MAP, GL_REFLECTION_MAP, 0 },
        { GL_NORMAL_MAP, GL_NORMAL_MAP, GL_NORMAL_MAP, 0 },
        { 0, 0, 0, 0 },
        { GL_EYE_LINEAR, GL_NORMAL_MAP, 0, 0 },
    };
    return modes[unit % 8][coord];
}

static void plane(int unit, int coord, GLfloat *p)
{
    p[0] = 0.5f + 0.1f * (float)unit - 0.2f * (float)coord;
    p[1] = -0.3f + 0.05f * (float)(unit * coord);
    p[2] = 0.2f * (float)coord - 0.1f;
    p[3] = 0.25f - 0.05f * (float)unit;
}

/* The state the reference reads back: the drawing modelview, each unit's texture matrix,
 * object planes and eye planes (in eye coordinates). */
static double modelview[16], texture[MAX_UNITS][16];
static double object_planes[MAX_UNITS][4][4], eye_planes[MAX_UNITS][4][4];

static void set_up_units(void)
{
    double plane_modelview[16];
    int unit, c, k;
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.2f, -0.1f, -0.5f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    tref_read_matrix(GL_MODELVIEW_MATRIX, plane_modelview);
    for (unit = 0; unit < units; unit++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glTranslatef(0.1f * (float)unit, -0.05f * (float)unit, 0.02f * (float)unit);
        glRotatef(17.0f * (float)unit, 1.0f, (float)unit, 2.0f);
        glScalef(1.0f + 0.1f * (float)unit, 1.0f, 1.0f - 0.05f * (float)unit);
        tref_read_matrix(GL_TEXTURE_MATRIX, texture[unit]);
        glMatrixMode(GL_MODELVIEW);
        for (c = 0; c < 4; c++) {
            GLfloat object_plane[4], eye_plane[4];
            GLenum coord = GL_S + (GLenum)c;
            plane(unit, c, object_plane);
            plane(unit, c + 4, eye_plane);
            glTexGenfv(coord, GL_OBJECT_PLANE, object_plane);
            glTexGenfv(coord, GL_EYE_PLANE, eye_plane);
            for (k = 0; k < 4; k++)
                object_planes[unit][c][k] = object_plane[k];
            tref_eye_plane(eye_plane, plane_modelview, eye_planes[unit][c]);
            if (gen_mode(unit, c)) {
                glTexGeni(coord, GL_TEXTURE_GEN_MODE, (GLint)gen_mode(unit, c));
                glEnable(GL_TEXTURE_GEN_S + (GLenum)c);
            }
        }
    }
    glActiveTexture(GL_TEXTURE0);
    glLoadIdentity();
    glTranslatef(0.1f, 0.3f, -3.0f);
    glRotatef(40.0f, 1.0f, 0.0f, 0.0f);
    glScalef(1.5f, 0.8f, 1.2f);
    tref_read_matrix(GL_MODELVIEW_MATRIX, modelview);
    glEnable(GL_NORMALIZE);
}

/* §2.11.4 and the texture matrix in double: unit `unit`'s coordinates of a vertex. */
static void reference(int unit, const GLfloat *object3, const GLfloat *normal,
                      const double *given, double *out)
{
    double object[4], coords[4];
    tref_vertex v;
    int c;
    object[0] = object3[0];
    object[1] = object3[1];
    object[2] = object3[2];
    object[3] = 1.0;
    tref_vertex_terms(modelview, object, normal, &v);
    for (c = 0; c < 4; c++) {
        switch (gen_mode(unit, c)) {
        case GL_OBJECT_LINEAR:
            coords[c] = tref_dot4(object_planes[unit][c], object);
            break;
        case GL_EYE_LINEAR:
            coords[c] = tref_dot4(eye_planes[unit][c], v.eye);
            break;
        case GL_SPHERE_MAP:
            coords[c] = v.sphere[c];
            break;
        case GL_REFLECTION_MAP:
            coords[c] = v.reflection[c];
            break;
        case GL_NORMAL_MAP:
            coords[c] = v.normal[c];
            break;
        default:
            coords[c] = given[c];
        }
    }
    tref_mul(texture[unit], coords, out);
}

/* The geometry: positions, normals and each unit's coordinates per vertex. */
static GLfloat positions[VERTICES][3], normals[VERTICES][3];

static void make_geometry(void)
{
    int i;
    for (i = 0; i < VERTICES; i++) {
        double t = i;
        positions[i][0] = (GLfloat)sin(t * 0.7);
        positions[i][1] = (GLfloat)(0.8 * cos(t * 1.3));
        positions[i][2] = (GLfloat)(0.3 * sin(t * 0.4));
        normals[i][0] = (GLfloat)cos(t * 0.9);
        normals[i][1] = 0.5f;
        normals[i][2] = (GLfloat)(sin(t * 0.5) + 0.2);
    }
}

/* What vertex `i` gives unit `unit` in immediate mode, and how (in the form the unit uses:
 * 4fv, 2d, 3i, 1s, padded as glMultiTexCoord pads). */
static void immediate_coords(int i, int unit, double *given)
{
    double s = 0.1 * i + unit, t = 0.05 * i - 0.3 * unit, r = 0.5 - 0.02 * i * unit;
    double q = 1.0 + 0.25 * unit;
    given[0] = s;
    given[1] = t;
    given[2] = 0.0;
    given[3] = 1.0;
    switch (unit % 4) {
    case 0:
        given[0] = (GLfloat)s;
        given[1] = (GLfloat)t;
        given[2] = (GLfloat)r;
        given[3] = (GLfloat)q;
        break;
    case 1:
        given[0] = (GLfloat)s;
        given[1] = (GLfloat)t;
        break;
    case 2:
        given[0] = (GLint)(10 * s);
        given[1] = (GLint)(10 * t);
        given[2] = (GLint)(10 * r);
        break;
    default:
        given[0] = (GLshort)(10 * s);
        given[1] = 0.0;
    }
}

static void send_immediate_coords(int i, int unit)
{
    double given[4];
    GLenum target = GL_TEXTURE0 + (GLenum)unit;
    GLfloat v[4];
    immediate_coords(i, unit, given);
    switch (unit % 4) {
    case 0:
        v[0] = (GLfloat)given[0];
        v[1] = (GLfloat)given[1];
        v[2] = (GLfloat)given[2];
        v[3] = (GLfloat)given[3];
        glMultiTexCoord4fv(target, v);
        break;
    case 1:
        glMultiTexCoord2d(target, given[0], given[1]);
        break;
    case 2:
        glMultiTexCoord3i(target, (GLint)given[0], (GLint)given[1], (GLint)given[2]);
        break;
    default:
        glMultiTexCoord1s(target, (GLshort)given[0]);
    }
}

/* Checks captured vertices first.. (vertex k drawn from element[k], its unit coordinates
 * from given(k, unit)) against the reference; returns the largest difference. */
typedef void (*given_fn)(int k, int unit, double *given);

static double check(const char *what, GLuint first, int count, const int *element,
                    given_fn given_of)
{
    static GLfloat got[MAX_UNITS][64][4];
    double worst = 0.0;
    int unit, k, c;
    char label[96];
    expect(fflCaptureVertexCount() == first + (GLuint)count, what);
    for (unit = 0; unit < units; unit++) {
        GLuint read = fflCaptureReadTexCoords(GL_TEXTURE0 + (GLenum)unit, first,
                                              (GLuint)count, &got[unit][0][0]);
        sprintf(label, "%s: unit %d read %u", what, unit, read);
        expect(read == (GLuint)count, label);
    }
    for (k = 0; k < count; k++) {
        int e = element[k];
        for (unit = 0; unit < units; unit++) {
            double given[4], want[4];
            given_of(k, unit, given);
            reference(unit, positions[e], normals[e], given, want);
            for (c = 0; c < 4; c++) {
                double error = fabs(got[unit][k][c] - want[c]);
                double scale = fabs(want[c]) > 1.0 ? fabs(want[c]) : 1.0;
                if (error / scale > worst)
                    worst = error / scale;
                if (error > TOLERANCE * scale) {
                    sprintf(label, "%s: vertex %d unit %d coordinate %d: %g, want %g", what, k,
                            unit, c, got[unit][k][c], want[c]);
                    expect(0, label);
                }
            }
        }
    }
    printf("%s units %d vertices %d max relative difference %.1e\n", what, (int)units, count,
           worst);
    return worst;
}

static int identity_elements[VERTICES];

/* Immediate mode: vertex k's own coordinates, but unit 6's stay vertex 0's. */
static void given_immediate(int k, int unit, double *given)
{
    immediate_coords(unit == 6 ? 0 : k, unit, given);
}

/* ---- arrays: unit u's array has its own type, size and stride; odd units 3, 5, 7 have
 * none (their current coordinates: current_coords); unit 1's is in a buffer object. ---- */
static struct {
    GLfloat pad0;
    GLfloat st[2];
    GLshort pad1;
} unit0_array[VERTICES]; /* GL_FLOAT, size 2, a stride of its own */
static GLshort unit2_array[VERTICES][3];  /* GL_SHORT, size 3, packed */
static GLdouble unit4_array[VERTICES][5]; /* GL_DOUBLE, size 4, stride 40 */
static GLint unit6_array[VERTICES];       /* GL_INT, size 1, packed */
static GLfloat unit1_data[VERTICES][4];   /* GL_FLOAT, size 4, in a buffer object */
static const double current_coords[4] = { 0.75, -0.5, 0.25, 2.0 };

static int has_array(int unit)
{
    return unit == 0 || unit == 1 || unit == 2 || unit == 4 || unit == 6;
}

static void array_coords(int element, int unit, double *given)
{
    int c;
    for (c = 0; c < 4; c++)
        given[c] = c == 3 ? 1.0 : 0.0;
    switch (unit) {
    case 0:
        given[0] = unit0_array[element].st[0];
        given[1] = unit0_array[element].st[1];
        break;
    case 1:
        for (c = 0; c < 4; c++)
            given[c] = unit1_data[element][c];
        break;
    case 2:
        for (c = 0; c < 3; c++)
            given[c] = unit2_array[element][c];
        break;
    case 4:
        for (c = 0; c < 4; c++)
            given[c] = unit4_array[element][c];
        break;
    case 6:
        given[0] = unit6_array[element];
        break;
    default:
        for (c = 0; c < 4; c++)
            given[c] = current_coords[c];
    }
}

static void fill_arrays(int shift)
{
    int i, c;
    for (i = 0; i < VERTICES; i++) {
        double t = i + shift;
        unit0_array[i].pad0 = -99.0f;
        unit0_array[i].st[0] = (GLfloat)(0.3 * t);
        unit0_array[i].st[1] = (GLfloat)(1.0 - 0.1 * t);
        unit0_array[i].pad1 = -99;
        for (c = 0; c < 3; c++)
            unit2_array[i][c] = (GLshort)(i * 3 + c - 20 + shift);
        for (c = 0; c < 5; c++)
            unit4_array[i][c] = 0.125 * t - 0.5 * c;
        unit6_array[i] = 7 - i + shift;
        for (c = 0; c < 4; c++)
            unit1_data[i][c] = (GLfloat)(0.01 * t * (c + 1) - 0.2);
    }
}

static GLuint buffer;

static void set_up_arrays(void)
{
    int unit;
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof unit1_data, unit1_data, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (unit = 0; unit < units; unit++) {
        glClientActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        switch (unit) {
        case 0:
            glTexCoordPointer(2, GL_FLOAT, sizeof unit0_array[0], &unit0_array[0].st[0]);
            break;
        case 1:
            glBindBuffer(GL_ARRAY_BUFFER, buffer);
            glTexCoordPointer(4, GL_FLOAT, 0, (const void *)0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            break;
        case 2:
            glTexCoordPointer(3, GL_SHORT, 0, unit2_array);
            break;
        case 4:
            glTexCoordPointer(4, GL_DOUBLE, 5 * sizeof(GLdouble), unit4_array);
            break;
        case 6:
            glTexCoordPointer(1, GL_INT, 0, unit6_array);
            break;
        default:
            break;
        }
        if (has_array(unit))
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glMultiTexCoord4dv(GL_TEXTURE0 + (GLenum)unit, current_coords);
    }
    glClientActiveTexture(GL_TEXTURE0);
}

static int drawn_element[64];

static void given_array(int k, int unit, double *given)
{
    array_coords(drawn_element[k], unit, given);
}

/* What a replayed list gives: the arrays as they were when it was compiled. */
static double compiled[64][MAX_UNITS][4];

static void given_compiled(int k, int unit, double *given)
{
    int c;
    for (c = 0; c < 4; c++)
        given[c] = compiled[k][unit][c];
}

/* A replayed glArrayElement(7): the arrays' element as compiled (taken by
 * snapshot_element when the list is compiled); the units without an array keep the current
 * coordinates of the replay, (-5, -6, 0, 1). */
static double compiled_element[MAX_UNITS][4];

static void snapshot_element(void)
{
    static const double replay_current[4] = { -5.0, -6.0, 0.0, 1.0 };
    int unit, c;
    for (unit = 0; unit < units; unit++) {
        if (has_array(unit))
            array_coords(7, unit, compiled_element[unit]);
        else
            for (c = 0; c < 4; c++)
                compiled_element[unit][c] = replay_current[c];
    }
}

static void given_compiled_element(int k, int unit, double *given)
{
    int c;
    (void)k;
    for (c = 0; c < 4; c++)
        given[c] = compiled_element[unit][c];
}

static void read_error(const char *what, GLenum want)
{
    GLenum error = glGetError();
    char label[96];
    sprintf(label, "%s: %s", what, ffl_error_name(error));
    printf("%s\n", label);
    expect(error == want, label);
}

/* Captures one draw of the arrays and checks it: `elements` are the array elements the
 * captured vertices first.. come from. */
static GLuint check_arrays(const char *what, GLuint first, const int *elements, int count)
{
    int k;
    for (k = 0; k < count; k++)
        drawn_element[k] = elements[k];
    check(what, first, count, drawn_element, given_array);
    return first + (GLuint)count;
}

int main(void)
{
    static const GLushort listed[12] = { 3, 7, 7, 1, 20, 3, 0, 23, 11, 11, 5, 3 };
    static const int multi[10] = { 2, 3, 4, 5, 6, 7, 15, 16, 17, 18 };
    static const int elements[2] = { 5, 17 };
    static const int listed_elements[12] = { 3, 7, 7, 1, 20, 3, 0, 23, 11, 11, 5, 3 };
    static const int list_elements[9] = { 0, 1, 2, 0, 1, 2, 3, 4, 5 };
    static const int seven[1] = { 7 };
    static GLfloat fb[4096];
    static FflCapturedVertex captured[8];
    static GLfloat unit_coords[MAX_UNITS][8][4];
    GLfloat probe[8] = { 9, 9, 9, 9, 9, 9, 9, 9 };
    GLfloat before[4], after[4];
    GLint value, fed, first[2] = { 2, 15 };
    GLsizei count[2] = { 6, 4 };
    GLuint list, element_list, at;
    int i, k, unit, c, same;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    printf("GL_MAX_TEXTURE_UNITS %d\n", (int)units);
    expect(units >= 2 && units <= MAX_UNITS, "GL_MAX_TEXTURE_UNITS");
    make_geometry();
    set_up_units();
    for (i = 0; i < VERTICES; i++)
        identity_elements[i] = i;

    /* Immediate mode: 19 vertices (more than two blocks of pending vertices). */
    fflCaptureBegin();
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 19; i++) {
        glNormal3fv(normals[i]);
        for (unit = 0; unit < units; unit++)
            if (unit != 6 || i == 0)
                send_immediate_coords(i, unit);
        glVertex3fv(positions[i]);
    }
    glEnd();
    fflCaptureEnd();
    check("immediate", 0, 19, identity_elements, given_immediate);

    /* Vertex arrays, every draw command. */
    fill_arrays(0);
    set_up_arrays();
    fflCaptureBegin();
    glDrawArrays(GL_TRIANGLES, 2, 18);
    at = check_arrays("glDrawArrays", 0, identity_elements + 2, 18);
    glDrawElements(GL_LINES, 12, GL_UNSIGNED_SHORT, listed);
    at = check_arrays("glDrawElements", at, listed_elements, 12);
    glDrawRangeElements(GL_POINTS, 0, 23, 12, GL_UNSIGNED_SHORT, listed);
    at = check_arrays("glDrawRangeElements", at, listed_elements, 12);
    glMultiDrawArrays(GL_LINE_STRIP, first, count, 2);
    at = check_arrays("glMultiDrawArrays", at, multi, 10);
    glBegin(GL_POINTS);
    glArrayElement(5);
    glArrayElement(17);
    glEnd();
    at = check_arrays("glArrayElement", at, elements, 2);
    fflCaptureEnd();
    read_error("arrays", GL_NO_ERROR);

    /* Display lists: glMultiTexCoord and an array draw compiled, replayed after the arrays
     * (client memory and the buffer object) and the current coordinates changed. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_POINTS);
    for (i = 0; i < 3; i++) {
        glNormal3fv(normals[i]);
        for (unit = 0; unit < units; unit++) {
            send_immediate_coords(i, unit);
            immediate_coords(i, unit, compiled[i][unit]);
        }
        glVertex3fv(positions[i]);
    }
    glEnd();
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEndList();
    for (k = 0; k < 6; k++)
        for (unit = 0; unit < units; unit++) {
            if (has_array(unit))
                array_coords(k, unit, compiled[3 + k][unit]);
            else /* the current coordinates the list's glMultiTexCoord left */
                immediate_coords(2, unit, compiled[3 + k][unit]);
        }
    element_list = glGenLists(1);
    glNewList(element_list, GL_COMPILE);
    glBegin(GL_POINTS);
    glArrayElement(7);
    glEnd();
    glEndList();
    snapshot_element();
    fill_arrays(5);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof unit1_data, unit1_data, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (unit = 0; unit < units; unit++)
        glMultiTexCoord2f(GL_TEXTURE0 + (GLenum)unit, -5.0f, -6.0f);
    fflCaptureBegin();
    glCallList(element_list);
    fflCaptureEnd();
    check("display list glArrayElement", 0, 1, seven, given_compiled_element);
    fflCaptureBegin();
    glCallList(list);
    fflCaptureEnd();
    check("display list", 0, 9, list_elements, given_compiled);
    read_error("display list", GL_NO_ERROR);

    /* Feedback reports unit 0's coordinates, as captured. */
    glDisableClientState(GL_VERTEX_ARRAY);
    glPushMatrix();
    glLoadIdentity();
    glFeedbackBuffer(4096, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    fflCaptureBegin();
    glBegin(GL_POINTS);
    for (i = 0; i < 4; i++) {
        for (unit = 0; unit < units; unit++)
            send_immediate_coords(i, unit);
        glNormal3fv(normals[i]);
        glVertex3f(0.5f * positions[i][0], 0.5f * positions[i][1], 0.5f * positions[i][2]);
    }
    glEnd();
    fflCaptureEnd();
    fed = glRenderMode(GL_RENDER);
    glPopMatrix();
    printf("feedback values %d\n", (int)fed);
    expect(fed == 4 * 13, "feedback: every point");
    expect(fflCaptureReadVertices(0, 4, captured) == 4, "feedback: captured points");
    for (unit = 0; unit < units; unit++)
        fflCaptureReadTexCoords(GL_TEXTURE0 + (GLenum)unit, 0, 4, &unit_coords[unit][0][0]);
    for (i = 0; i < 4 && fed == 4 * 13; i++) {
        const GLfloat *point = fb + 13 * i;
        expect(point[0] == GL_POINT_TOKEN, "feedback: point token");
        for (c = 0; c < 4; c++) {
            expect(point[9 + c] == unit_coords[0][i][c], "feedback: unit 0's coordinates");
            expect(captured[i].tex_coord[c] == unit_coords[0][i][c],
                   "fflCaptureReadVertices: unit 0's coordinates");
        }
        for (unit = 1; unit < units; unit++) {
            same = 1;
            for (c = 0; c < 4; c++)
                same = same && point[9 + c] == unit_coords[unit][i][c];
            expect(!same, "feedback: not another unit's coordinates");
        }
    }

    /* Units beyond the limit: GL_INVALID_ENUM, nothing changes. */
    glActiveTexture(GL_TEXTURE2);
    glClientActiveTexture(GL_TEXTURE1);
    glActiveTexture(GL_TEXTURE0 + (GLenum)units);
    read_error("glActiveTexture(GL_TEXTURE0 + units)", GL_INVALID_ENUM);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
    expect(value == GL_TEXTURE2, "glActiveTexture beyond the limit changes nothing");
    glClientActiveTexture(GL_TEXTURE0 + (GLenum)units);
    read_error("glClientActiveTexture(GL_TEXTURE0 + units)", GL_INVALID_ENUM);
    glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &value);
    expect(value == GL_TEXTURE1, "glClientActiveTexture beyond the limit changes nothing");
    glActiveTexture(GL_TEXTURE0 + (GLenum)units - 1);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, before);
    glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)units, 1, 2, 3, 4);
    read_error("glMultiTexCoord4f(GL_TEXTURE0 + units)", GL_INVALID_ENUM);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, after);
    expect(memcmp(before, after, sizeof before) == 0, "glMultiTexCoord beyond the limit");
    glActiveTexture(GL_TEXTURE0);
    glClientActiveTexture(GL_TEXTURE0);
    expect(fflCaptureReadTexCoords(GL_TEXTURE0 + (GLenum)units, 0, 2, probe) == 0,
           "fflCaptureReadTexCoords beyond the limit reads nothing");
    read_error("fflCaptureReadTexCoords(GL_TEXTURE0 + units)", GL_INVALID_ENUM);
    for (c = 0; c < 8; c++)
        expect(probe[c] == 9.0f, "fflCaptureReadTexCoords beyond the limit writes nothing");
    expect(fflCaptureReadTexCoords(GL_TEXTURE1, 0, 2, NULL) == 0, "NULL");
    read_error("fflCaptureReadTexCoords into NULL", GL_INVALID_VALUE);
    expect(fflCaptureReadTexCoords(GL_TEXTURE1, 3, 5, probe) == 1, "the last vertex only");
    expect(memcmp(probe, unit_coords[1][3], 4 * sizeof(GLfloat)) == 0, "the last vertex");
    expect(fflCaptureReadTexCoords(GL_TEXTURE1, 4, 1, probe) == 0, "past the end");
    read_error("reads past the end", GL_NO_ERROR);

    printf("%s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
