/* ffl-test: differential */
/*
 * The vertex array draws (§2.8) in every primitive mode, lit, into
 * feedback: glDrawArrays from a first element other than 0, glDrawElements
 * with unsigned byte, short and int indices (out of order; no index repeats
 * within a triangle: fflight and Mesa face zero-area triangles differently),
 * glDrawRangeElements with a range wider than the indices used,
 * glArrayElement between glBegin and glEnd (mixed with immediate-mode calls).
 * After glArrayElement the current color and normal are the element's; the
 * tracked material follows. Each draw is marked by a glPassThrough, so
 * segments print with the token the spec gives them. (A draw with the vertex
 * array disabled is in arrays_osmesa_diff_no_vertex_array.c.)
 *
 * osmesa-known: line-reset
 * (OSMesa feeds back GL_LINE_TOKEN where the spec resets the stipple; see
 * prim_lines.c.)
 */
#include "ffl_test.h"

#define COUNT 12
#define FEEDBACK 8192

static GLfloat positions[COUNT][3];
static GLdouble normals[COUNT][3];
static GLubyte colors[COUNT][4];
static GLfloat texcoords[COUNT][2];

static GLfloat feedback[FEEDBACK];
static ffl_fb fb;

static void start(GLenum mode)
{
    ffl_fb_draw_start(&fb, feedback, FEEDBACK, GL_4D_COLOR_TEXTURE, mode);
}

static int finish(const char *label)
{
    return ffl_fb_draw_finish(&fb, label);
}

int main(void)
{
    static const char *mode_names[10] = { "points", "lines", "line_loop", "line_strip",
                                          "triangles", "triangle_strip", "triangle_fan",
                                          "quads", "quad_strip", "polygon" };
    static const GLfloat light[4] = { 0.2f, 0.6f, 1.0f, 0.0f };
    static const GLfloat specular[4] = { 0.5f, 0.5f, 0.5f, 1.0f };
    static const GLubyte ub_indices[9] = { 3, 1, 4, 0, 5, 9, 2, 6, 8 };
    static const GLushort us_indices[8] = { 11, 0, 10, 1, 9, 2, 8, 3 };
    static const GLuint ui_indices[10] = { 4, 5, 6, 7, 8, 9, 10, 11, 0, 1 };
    char label[64];
    GLfloat current[4], diffuse[4];
    ffl_rng rng;
    int failed = 0, i, mode;

    ffl_test_init();
    ffl_rng_seed(&rng, 7);
    /* A convex ring of vertices (polygons must be convex), slightly tilted. */
    for (i = 0; i < COUNT; i++) {
        double angle = 2 * FFL_PI * i / COUNT;
        positions[i][0] = (GLfloat)(2.5 * cos(angle));
        positions[i][1] = (GLfloat)(2.0 * sin(angle));
        positions[i][2] = (GLfloat)(0.3 * cos(angle) - 0.2 * sin(angle));
        normals[i][0] = ffl_rng_unit(&rng) - 0.5;
        normals[i][1] = ffl_rng_unit(&rng) - 0.5;
        normals[i][2] = 1.0;
        colors[i][0] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][1] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][2] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][3] = (GLubyte)ffl_rng_int(&rng, 256);
        texcoords[i][0] = ffl_rng_float(&rng, -1, 1);
        texcoords[i][1] = ffl_rng_float(&rng, -1, 1);
    }
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 50);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -8);
    glRotatef(15, 1, 0, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);

    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_DOUBLE, 0, normals);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);

    for (mode = GL_POINTS; mode <= GL_POLYGON; mode++) {
        sprintf(label, "arrays %s", mode_names[mode]);
        start((GLenum)mode);
        glDrawArrays((GLenum)mode, 2, 9);
        failed |= finish(label);

        sprintf(label, "ubyte %s", mode_names[mode]);
        start((GLenum)mode);
        glDrawElements((GLenum)mode, 9, GL_UNSIGNED_BYTE, ub_indices);
        failed |= finish(label);

        sprintf(label, "ushort %s", mode_names[mode]);
        start((GLenum)mode);
        glDrawElements((GLenum)mode, 8, GL_UNSIGNED_SHORT, us_indices);
        failed |= finish(label);

        sprintf(label, "uint %s", mode_names[mode]);
        start((GLenum)mode);
        glDrawElements((GLenum)mode, 10, GL_UNSIGNED_INT, ui_indices);
        failed |= finish(label);

        sprintf(label, "range %s", mode_names[mode]);
        start((GLenum)mode);
        glDrawRangeElements((GLenum)mode, 0, COUNT - 1, 8, GL_UNSIGNED_SHORT, us_indices);
        failed |= finish(label);

        sprintf(label, "element %s", mode_names[mode]);
        start((GLenum)mode);
        glBegin((GLenum)mode);
        for (i = 0; i < 7; i++) {
            glArrayElement((i * 5) % COUNT);
            if (i == 3) {
                /* Immediate-mode calls mix with array elements. */
                glColor3f(0.9f, 0.1f, 0.4f);
                glNormal3f(0, 0, 1);
                glTexCoord2f(0.5f, 0.5f);
                glVertex3f(0.2f, 0.1f, 0.0f);
            }
        }
        glEnd();
        failed |= finish(label);
    }

    /* glArrayElement outside glBegin/glEnd: the current color and normal
     * become the element's, and color material follows the color. */
    glArrayElement(5);
    glGetFloatv(GL_CURRENT_COLOR, current);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    printf("after_array_element");
    ffl_pfv("color", current, 4);
    ffl_pfv("diffuse", diffuse, 4);
    glGetFloatv(GL_CURRENT_NORMAL, current);
    ffl_pfv("normal", current, 3);
    printf(" error %s\n", ffl_error_name(glGetError()));

    return failed;
}
