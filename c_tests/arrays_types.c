/* ffl-test: differential */
/*
 * Vertex arrays (§2.8) of every type, size and stride, drawn with glDrawArrays
 * into feedback (GL_4D_COLOR_TEXTURE): vertex arrays of shorts, ints, floats
 * and doubles with 2, 3 and 4 components; normals of floats and doubles; colors
 * of unsigned bytes, shorts and ints (c / (2^b - 1)), floats and doubles with 3
 * and 4 components; texture coordinates of every type with 1 to 4 components;
 * an edge flag array (in fill mode: OSMesa feeds back nothing in the point and
 * line polygon modes when edge flags are given). Each array packed (stride 0), at an unaligned stride and at a
 * padded one, the other arrays fixed. Lit (two lights, one a spot, two-sided,
 * separate specular, color material) and unlit, in
 * several primitive modes. (No texture matrix: OSMesa's feedback ignores it.)
 *
 * Signed integer colors and normals are left to
 * arrays_osmesa_diff_signed_normalization.c: OSMesa normalizes them as GL 4.2
 * does, c / (2^(b-1) - 1), not as table 2.9 says.
 */
#include "ffl_test.h"
#include <string.h>

#define COUNT 7
#define MAX_ELEMENT 32
#define BUFFER (COUNT * (MAX_ELEMENT + 16))
#define FEEDBACK 4096

static ffl_rng rng;

static int type_size(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_DOUBLE: return 8;
    default: return 4;
    }
}

static const char *type_name(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return "ubyte";
    case GL_SHORT: return "short";
    case GL_UNSIGNED_SHORT: return "ushort";
    case GL_INT: return "int";
    case GL_UNSIGNED_INT: return "uint";
    case GL_FLOAT: return "float";
    case GL_DOUBLE: return "double";
    default: return "?";
    }
}

/* Writes one component of `type` at p. Coordinates (`coordinate` set) are
 * integers in [-30, 30] (vertices drawn scaled by 0.1, so that triangles are
 * rarely degenerate: fflight and Mesa face zero-area triangles differently)
 * or floats in [-3, 3]; colors use the full unsigned range or floats in
 * [-0.2, 1.2]. */
static void put(unsigned char *p, GLenum type, int coordinate, double value)
{
    GLushort us; GLshort s; GLint i; GLuint ui; GLfloat f; GLdouble d; GLubyte ub;
    (void)coordinate;
    switch (type) {
    case GL_UNSIGNED_BYTE: ub = (GLubyte)value; memcpy(p, &ub, 1); break;
    case GL_SHORT: s = (GLshort)value; memcpy(p, &s, 2); break;
    case GL_UNSIGNED_SHORT: us = (GLushort)value; memcpy(p, &us, 2); break;
    case GL_INT: i = (GLint)value; memcpy(p, &i, 4); break;
    case GL_UNSIGNED_INT: ui = (GLuint)value; memcpy(p, &ui, 4); break;
    case GL_FLOAT: f = (GLfloat)value; memcpy(p, &f, 4); break;
    default: d = value; memcpy(p, &d, 8); break;
    }
}

static double random_value(GLenum type, int coordinate)
{
    if (coordinate) {
        if (type == GL_FLOAT || type == GL_DOUBLE)
            return ffl_rng_unit(&rng) * 6.0 - 3.0;
        return (double)(ffl_rng_int(&rng, 61) - 30); /* drawn scaled by 0.1 */
    }
    switch (type) {
    case GL_UNSIGNED_BYTE: return ffl_rng_int(&rng, 256);
    case GL_UNSIGNED_SHORT: return ffl_rng_int(&rng, 65536);
    case GL_UNSIGNED_INT: return (double)(ffl_rng_u64(&rng) >> 32);
    case GL_FLOAT: return ffl_rng_unit(&rng) * 1.4 - 0.2;
    default: return ffl_rng_unit(&rng) * 1.4 - 0.2; /* double: more digits than a float */
    }
}

/* Fills `count` elements of `size` components at `stride` (0: packed). A
 * fourth coordinate is positive and moderate (clipping stays well
 * conditioned), 1 when `w_one` (OSMesa lights w != 1 differently, see
 * osmesa_diff_vertex_w.c). */
static void fill(unsigned char *buf, GLenum type, int size, int stride, int coordinate, int w_one)
{
    int element = size * type_size(type);
    int step = stride ? stride : element;
    int i, c;
    memset(buf, 0xA5, BUFFER);
    for (i = 0; i < COUNT; i++)
        for (c = 0; c < size; c++) {
            double v = random_value(type, coordinate);
            if (c == 3 && coordinate)
                v = w_one ? 1.0 : (type == GL_FLOAT || type == GL_DOUBLE)
                    ? 0.5 + 1.5 * ffl_rng_unit(&rng) : (double)(1 + ffl_rng_int(&rng, 3));
            put(buf + i * step + c * type_size(type), type, coordinate, v);
        }
}

static unsigned char vertices[BUFFER], normals[BUFFER], colors[BUFFER], texcoords[BUFFER];
static GLboolean flags[COUNT * 3];

/* The fixed arrays the varied one is drawn with. */
static void fixed_arrays(int lit)
{
    int i;
    fill(vertices, GL_FLOAT, 3, 0, 1, 1);
    glVertexPointer(3, GL_FLOAT, 0, vertices);
    fill(normals, GL_FLOAT, 3, 0, 0, 0);
    glNormalPointer(GL_FLOAT, 0, normals);
    fill(colors, GL_UNSIGNED_BYTE, 4, 0, 0, 0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    fill(texcoords, GL_FLOAT, 2, 0, 1, 0);
    glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
    for (i = 0; i < COUNT * 3; i++)
        flags[i] = (GLboolean)(ffl_rng_int(&rng, 3) != 0);
    glEdgeFlagPointer(3, flags);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    if (lit)
        glEnableClientState(GL_NORMAL_ARRAY);
    else
        glDisableClientState(GL_NORMAL_ARRAY);
}

static int draw(const char *label, GLenum mode)
{
    static GLfloat buf[FEEDBACK];
    GLint n;
    glFeedbackBuffer(FEEDBACK, GL_4D_COLOR_TEXTURE, buf);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(mode, 0, COUNT);
    n = glRenderMode(GL_RENDER);
    printf("%s count %d error %s\n", label, (int)n, ffl_error_name(glGetError()));
    if (n < 0)
        return 1;
    return ffl_print_feedback(label, buf, n, GL_4D_COLOR_TEXTURE);
}

static void set_lit_state(void)
{
    static const GLfloat light0[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    static const GLfloat spec0[4] = { 0.9f, 0.8f, 0.7f, 1.0f };
    static const GLfloat light1[4] = { -2.0f, 1.0f, -6.0f, 1.0f };
    static const GLfloat diffuse1[4] = { 0.4f, 0.7f, 0.2f, 1.0f };
    static const GLfloat spot1[3] = { 1.0f, -0.5f, -1.0f };
    static const GLfloat mat_spec[4] = { 0.6f, 0.6f, 0.6f, 1.0f };
    static const GLfloat back_emission[4] = { 0.1f, 0.0f, 0.2f, 1.0f };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_POSITION, light0);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec0);
    glLightfv(GL_LIGHT1, GL_POSITION, light1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse1);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot1);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 80.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.0f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glMaterialfv(GL_FRONT, GL_SPECULAR, mat_spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
    glMaterialfv(GL_BACK, GL_EMISSION, back_emission);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
}

int main(void)
{
    static const GLenum vertex_types[4] = { GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE };
    static const GLenum color_types[5] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT,
                                           GL_FLOAT, GL_DOUBLE };
    static const GLenum normal_types[2] = { GL_FLOAT, GL_DOUBLE };
    static const GLenum modes[4] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_POINTS, GL_POLYGON };
    char label[96];
    int failed = 0, lit, t, size, s, k = 0;

    ffl_test_init();
    ffl_rng_seed(&rng, 20240611);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 50);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -10);
    glRotatef(20, 1, 1, 0);

    for (lit = 1; lit >= 0; lit--) {
        const char *tag = lit ? "lit" : "unlit";
        if (lit)
            set_lit_state();
        else
            glDisable(GL_LIGHTING);
        for (t = 0; t < 4; t++)
            for (size = 2; size <= 4; size++)
                for (s = 0; s < 3; s++) {
                    int element = size * type_size(vertex_types[t]);
                    int stride = s == 0 ? 0 : s == 1 ? element + 1 : element + 13;
                    fixed_arrays(lit);
                    fill(vertices, vertex_types[t], size, stride, 1, lit);
                    glVertexPointer(size, vertex_types[t], stride, vertices);
                    sprintf(label, "%s vertex %s %d stride %d", tag, type_name(vertex_types[t]), size, stride);
                    glPushMatrix();
                    if (vertex_types[t] == GL_SHORT || vertex_types[t] == GL_INT)
                        glScalef(0.1f, 0.1f, 0.1f);
                    failed |= draw(label, modes[k++ % 4]);
                    glPopMatrix();
                }
        for (t = 0; lit && t < 2; t++)
            for (s = 0; s < 3; s++) {
                int stride = s == 0 ? 0 : s == 1 ? 3 * type_size(normal_types[t]) + 1 : 40;
                fixed_arrays(lit);
                fill(normals, normal_types[t], 3, stride, 0, 0);
                glNormalPointer(normal_types[t], stride, normals);
                sprintf(label, "%s normal %s stride %d", tag, type_name(normal_types[t]), stride);
                failed |= draw(label, modes[k++ % 4]);
            }
        for (t = 0; t < 5; t++)
            for (size = 3; size <= 4; size++)
                for (s = 0; s < 3; s++) {
                    int element = size * type_size(color_types[t]);
                    int stride = s == 0 ? 0 : s == 1 ? element + 1 : element + 13;
                    fixed_arrays(lit);
                    fill(colors, color_types[t], size, stride, 0, 0);
                    glColorPointer(size, color_types[t], stride, colors);
                    sprintf(label, "%s color %s %d stride %d", tag, type_name(color_types[t]), size, stride);
                    failed |= draw(label, modes[k++ % 4]);
                }
        for (t = 0; t < 4; t++)
            for (size = 1; size <= 4; size++)
                for (s = 0; s < 3; s++) {
                    int element = size * type_size(vertex_types[t]);
                    int stride = s == 0 ? 0 : s == 1 ? element + 1 : element + 13;
                    fixed_arrays(lit);
                    fill(texcoords, vertex_types[t], size, stride, 1, 0);
                    glTexCoordPointer(size, vertex_types[t], stride, texcoords);
                    sprintf(label, "%s texcoord %s %d stride %d", tag, type_name(vertex_types[t]), size, stride);
                    failed |= draw(label, modes[k++ % 4]);
                }
    }
    printf("error %s\n", ffl_error_name(glGetError()));
    return failed;
}
