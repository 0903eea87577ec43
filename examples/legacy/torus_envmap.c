/*
 * A classic environment-mapping program in the style of the Red Book's texgen examples: a
 * lit torus (quad strips with a normal per vertex) whose texture coordinates s and t come
 * from GL_SPHERE_MAP generation, textured with a procedural sky-and-ground environment
 * image, drawn in feedback mode. Written against the system <GL/gl.h> only, as init(),
 * reshape() and display(); it runs unchanged against fflight and against OSMesa (with
 * -DFFL_OSMESA, which only adds a context). c_tests/legacy_torus_envmap.c compares the
 * two and checks the generated coordinates against the spec's formula.
 */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include "legacy_feedback.h"

#define TORUS_PI 3.14159265358979323846
#define ENVIRONMENT_SIZE 32
#define TORUS_FEEDBACK_SIZE 16384

static GLubyte environment[ENVIRONMENT_SIZE][ENVIRONMENT_SIZE][3];
static GLuint environment_texture;

/* A sphere map of a blue sky over a brown ground, brighter towards the horizon. */
static void make_environment(void)
{
    int i, j;
    for (i = 0; i < ENVIRONMENT_SIZE; i++)
        for (j = 0; j < ENVIRONMENT_SIZE; j++) {
            double y = (i + 0.5) / ENVIRONMENT_SIZE * 2.0 - 1.0;
            double glow = 1.0 - fabs(y);
            if (y > 0.0) {
                environment[i][j][0] = (GLubyte)(60 + 150 * glow);
                environment[i][j][1] = (GLubyte)(110 + 120 * glow);
                environment[i][j][2] = 255;
            } else {
                environment[i][j][0] = (GLubyte)(90 + 120 * glow);
                environment[i][j][1] = (GLubyte)(60 + 100 * glow);
                environment[i][j][2] = (GLubyte)(30 + 60 * glow);
            }
        }
}

static void init(void)
{
    static const GLfloat light_position[4] = { -1.0f, 2.0f, 4.0f, 0.0f };
    static const GLfloat chrome_diffuse[4] = { 0.55f, 0.55f, 0.6f, 1.0f };
    static const GLfloat chrome_specular[4] = { 0.9f, 0.9f, 0.9f, 1.0f };

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);

    make_environment();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &environment_texture);
    glBindTexture(GL_TEXTURE_2D, environment_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, ENVIRONMENT_SIZE, ENVIRONMENT_SIZE, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, environment);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_2D);

    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, chrome_diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, chrome_specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A torus around the z axis: `rings` quad strips around the tube of radius `tube`, each
 * `sides` quads long, the tube's centre at distance `radius` from the axis. */
static void torus(GLfloat tube, GLfloat radius, int sides, int rings)
{
    int i, j;
    for (i = 0; i < rings; i++) {
        double theta0 = 2.0 * TORUS_PI * i / rings, theta1 = 2.0 * TORUS_PI * (i + 1) / rings;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= sides; j++) {
            double phi = 2.0 * TORUS_PI * j / sides;
            double ring = radius + tube * cos(phi);
            glNormal3f((GLfloat)(cos(theta1) * cos(phi)), (GLfloat)(sin(theta1) * cos(phi)),
                       (GLfloat)sin(phi));
            glVertex3f((GLfloat)(cos(theta1) * ring), (GLfloat)(sin(theta1) * ring),
                       (GLfloat)(tube * sin(phi)));
            glNormal3f((GLfloat)(cos(theta0) * cos(phi)), (GLfloat)(sin(theta0) * cos(phi)),
                       (GLfloat)sin(phi));
            glVertex3f((GLfloat)(cos(theta0) * ring), (GLfloat)(sin(theta0) * ring),
                       (GLfloat)(tube * sin(phi)));
        }
        glEnd();
    }
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    torus(0.35f, 1.0f, 6, 8);
    glPopMatrix();
    glFlush();
}

static GLfloat torus_feedback[TORUS_FEEDBACK_SIZE];

int main(void)
{
    if (legacy_make_current() != 0)
        return 1;
    init();
    reshape(64, 64);
    glFeedbackBuffer(TORUS_FEEDBACK_SIZE, GL_3D_COLOR_TEXTURE, torus_feedback);
    glRenderMode(GL_FEEDBACK);
    display();
    legacy_print_feedback("torus", torus_feedback, glRenderMode(GL_RENDER),
                          GL_3D_COLOR_TEXTURE);
    printf("torus error %d\n", (int)glGetError());
    return 0;
}
