/*
 * A classic multitexturing program in the style of the Red Book's multitex.c: a lit quad
 * (a 3 x 3 grid of GL_QUADS) with two textures, a checkerboard on unit 0 tiled twice by
 * unit 0's texture matrix and a gradient on unit 1 turned by 45 degrees about its centre
 * by unit 1's texture matrix, each vertex given one coordinate pair per unit with
 * glMultiTexCoord2f; drawn in feedback mode, which returns unit 0's coordinates (§5.3).
 * Written against the system <GL/gl.h> only, as init(), reshape() and display(); it runs
 * unchanged against fflight and against OSMesa (with -DFFL_OSMESA, which only adds a
 * context). c_tests/legacy_multitexture_quad.c compares the two.
 */
#include <GL/gl.h>
#include <stdio.h>
#include "legacy_feedback.h"

#define QUAD_IMAGE_SIZE 16
#define QUAD_GRID 3
#define QUAD_FEEDBACK_SIZE 8192

static GLubyte checker[QUAD_IMAGE_SIZE][QUAD_IMAGE_SIZE][4];
static GLubyte gradient[QUAD_IMAGE_SIZE][QUAD_IMAGE_SIZE][4];
static GLuint textures[2];

static void make_images(void)
{
    int i, j;
    for (i = 0; i < QUAD_IMAGE_SIZE; i++)
        for (j = 0; j < QUAD_IMAGE_SIZE; j++) {
            GLubyte c = (GLubyte)((((i & 4) == 0) ^ ((j & 4) == 0)) * 255);
            checker[i][j][0] = checker[i][j][1] = checker[i][j][2] = c;
            checker[i][j][3] = 255;
            gradient[i][j][0] = (GLubyte)(i * 16);
            gradient[i][j][1] = (GLubyte)(j * 16);
            gradient[i][j][2] = 128;
            gradient[i][j][3] = 255;
        }
}

static void texture_unit(GLenum unit, GLuint texture, const GLubyte *image, GLint env_mode)
{
    glActiveTexture(unit);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, QUAD_IMAGE_SIZE, QUAD_IMAGE_SIZE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, image);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env_mode);
    glEnable(GL_TEXTURE_2D);
}

static void init(void)
{
    static const GLfloat light_position[4] = { 1.0f, 1.5f, 2.0f, 1.0f };
    static const GLfloat light_diffuse[4] = { 0.9f, 0.85f, 0.8f, 1.0f };
    static const GLfloat material_specular[4] = { 0.6f, 0.6f, 0.6f, 1.0f };

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    make_images();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, textures);
    texture_unit(GL_TEXTURE0, textures[0], &checker[0][0][0], GL_MODULATE);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glScalef(2.0f, 2.0f, 1.0f);
    texture_unit(GL_TEXTURE1, textures[1], &gradient[0][0][0], GL_ADD);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.0f);
    glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
    glTranslatef(-0.5f, -0.5f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE0);

    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, material_specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 16.0f);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.6f);
}

/* The corner (i, j) of the grid: position in [-1.5, 1.5]^2, coordinates in [0, 1]^2. */
static void corner(int i, int j)
{
    GLfloat s = (GLfloat)i / QUAD_GRID, t = (GLfloat)j / QUAD_GRID;
    glMultiTexCoord2f(GL_TEXTURE0, s, t);
    glMultiTexCoord2f(GL_TEXTURE1, s, t);
    glVertex3f(3.0f * s - 1.5f, 3.0f * t - 1.5f, 0.0f);
}

static void display(void)
{
    int i, j;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(15.0f, 0.0f, 0.0f, 1.0f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_QUADS);
    for (i = 0; i < QUAD_GRID; i++)
        for (j = 0; j < QUAD_GRID; j++) {
            corner(i, j);
            corner(i + 1, j);
            corner(i + 1, j + 1);
            corner(i, j + 1);
        }
    glEnd();
    glPopMatrix();
    glFlush();
}

static GLfloat quad_feedback[QUAD_FEEDBACK_SIZE];

int main(void)
{
    int unit;
    if (legacy_make_current() != 0)
        return 1;
    init();
    reshape(64, 64);
    glFeedbackBuffer(QUAD_FEEDBACK_SIZE, GL_3D_COLOR_TEXTURE, quad_feedback);
    glRenderMode(GL_FEEDBACK);
    display();
    legacy_print_feedback("quad", quad_feedback, glRenderMode(GL_RENDER), GL_3D_COLOR_TEXTURE);
    /* Each unit's coordinates at a raster position, through its own texture matrix. */
    glRasterPos3f(0.25f, -0.5f, 0.0f);
    for (unit = 0; unit < 2; unit++) {
        GLfloat strq[4];
        glActiveTexture((GLenum)(GL_TEXTURE0 + unit));
        glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, strq);
        printf("raster unit %d strq %.9g %.9g %.9g %.9g\n", unit, strq[0], strq[1], strq[2],
               strq[3]);
    }
    printf("quad error %d\n", (int)glGetError());
    return 0;
}
