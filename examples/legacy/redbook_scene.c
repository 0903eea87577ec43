/*
 * A classic OpenGL 1.x program in the style of the Red Book: no GLUT, no GLU, its own
 * tessellation of a sphere and a torus, written against the system <GL/gl.h> only. It sets
 * the state such programs set (clear color, depth test, blending, fog, a texture with its
 * environment, two-sided lighting, three lights and two materials), builds display lists,
 * brackets changes with glPushAttrib/glPopAttrib, and draws the scene in feedback mode,
 * printing every fed-back polygon.
 *
 * It runs unchanged against fflight and against Mesa's OSMesa (built with -DFFL_OSMESA,
 * which only adds an OSMesa context): c_tests/legacy_redbook_scene.c builds it both ways
 * and the test suite compares the two outputs.
 *
 *   cc -std=c99 examples/legacy/redbook_scene.c target/release/libfflight.a -lm -lpthread -ldl
 */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#ifdef FFL_OSMESA
#include <GL/osmesa.h>
#endif

#define PI 3.14159265358979323846
#define FEEDBACK_SIZE 32768

static GLfloat feedback[FEEDBACK_SIZE];

/* A sphere of `slices` x `stacks` quads, with normals and texture coordinates. */
static void sphere(double radius, int slices, int stacks)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        double phi0 = PI * i / stacks - PI / 2, phi1 = PI * (i + 1) / stacks - PI / 2;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= slices; j++) {
            double theta = 2 * PI * j / slices;
            double x0 = cos(phi0) * cos(theta), y0 = sin(phi0), z0 = cos(phi0) * sin(theta);
            double x1 = cos(phi1) * cos(theta), y1 = sin(phi1), z1 = cos(phi1) * sin(theta);
            glNormal3d(x1, y1, z1);
            glTexCoord2d((double)j / slices, (double)(i + 1) / stacks);
            glVertex3d(radius * x1, radius * y1, radius * z1);
            glNormal3d(x0, y0, z0);
            glTexCoord2d((double)j / slices, (double)i / stacks);
            glVertex3d(radius * x0, radius * y0, radius * z0);
        }
        glEnd();
    }
}

/* A torus as triangles (the Red Book's own torus, in quads split by hand). */
static void torus(double inner, double outer, int sides, int rings)
{
    int i, j, k;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < rings; i++)
        for (j = 0; j < sides; j++) {
            static const int corners[6][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 },
                                               { 0, 0 }, { 1, 1 }, { 0, 1 } };
            for (k = 0; k < 6; k++) {
                double theta = 2 * PI * (i + corners[k][0]) / rings;
                double phi = 2 * PI * (j + corners[k][1]) / sides;
                double nx = cos(theta) * cos(phi), ny = sin(theta) * cos(phi), nz = sin(phi);
                double r = outer + inner * cos(phi);
                glNormal3d(nx, ny, nz);
                glVertex3d(r * cos(theta), r * sin(theta), inner * sin(phi));
            }
        }
    glEnd();
}

static void print_feedback(const char *tag, GLint n)
{
    GLint i = 0;
    int k, count;
    printf("%s count %d\n", tag, (int)n);
    while (i < n) {
        GLint token = (GLint)feedback[i++];
        if (token == GL_POLYGON_TOKEN && i < n) {
            count = (int)feedback[i++];
        } else if (token == GL_POINT_TOKEN) {
            count = 1;
        } else if (token == GL_PASS_THROUGH_TOKEN && i < n) {
            printf("%s pass %g\n", tag, (double)feedback[i++]);
            continue;
        } else {
            printf("%s unexpected token %d\n", tag, (int)token);
            return;
        }
        printf("%s %s %d\n", tag, token == GL_POINT_TOKEN ? "point" : "polygon", count);
        for (k = 0; k < count && i + 12 <= n; k++, i += 12)
            printf("%s  v xyzw %.9g %.9g %.9g %.9g rgba %.9g %.9g %.9g %.9g strq %.9g %.9g "
                   "%.9g %.9g\n",
                   tag, feedback[i], feedback[i + 1], feedback[i + 2], feedback[i + 3],
                   feedback[i + 4], feedback[i + 5], feedback[i + 6], feedback[i + 7],
                   feedback[i + 8], feedback[i + 9], feedback[i + 10], feedback[i + 11]);
    }
}

int main(void)
{
    static const GLfloat light0_position[4] = { 2.0f, 3.0f, 4.0f, 0.0f };
    static const GLfloat light1_position[4] = { -3.0f, 1.0f, 2.0f, 1.0f };
    static const GLfloat light1_diffuse[4] = { 0.2f, 0.4f, 1.0f, 1.0f };
    static const GLfloat light2_position[4] = { 0.0f, -2.0f, 3.0f, 1.0f };
    static const GLfloat light2_direction[3] = { 0.0f, 0.5f, -1.0f };
    static const GLfloat red_plastic[4] = { 0.8f, 0.1f, 0.1f, 1.0f };
    static const GLfloat gold[4] = { 0.75f, 0.6f, 0.2f, 0.8f };
    static const GLfloat white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    static const GLfloat fog_color[4] = { 0.5f, 0.5f, 0.5f, 1.0f };
    static const GLfloat model_ambient[4] = { 0.1f, 0.1f, 0.15f, 1.0f };
    GLubyte checker[8][8][4];
    GLuint texture, lists;
    int i, j;
#ifdef FFL_OSMESA
    static GLubyte color_buffer[256 * 256 * 4];
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (context == NULL || !OSMesaMakeCurrent(context, color_buffer, GL_UNSIGNED_BYTE, 256, 256))
        return 1;
#endif

    /* The usual initialization. */
    glViewport(0, 0, 256, 256);
    glClearColor(0.0f, 0.0f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogf(GL_FOG_START, 4.0f);
    glFogf(GL_FOG_END, 12.0f);
    glHint(GL_FOG_HINT, GL_NICEST);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_CULL_FACE);

    /* A checkerboard texture, modulated. */
    for (i = 0; i < 8; i++)
        for (j = 0; j < 8; j++) {
            GLubyte c = ((i ^ j) & 1) ? 255 : 64;
            checker[i][j][0] = c;
            checker[i][j][1] = c;
            checker[i][j][2] = c;
            checker[i][j][3] = 255;
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    /* Lights and materials. */
    glEnable(GL_LIGHTING);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glLightfv(GL_LIGHT0, GL_POSITION, light0_position);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT1, GL_POSITION, light1_position);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, light1_diffuse);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT2, GL_POSITION, light2_position);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, light2_direction);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 40.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8.0f);
    glEnable(GL_LIGHT2);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);

    /* Display lists: each object with its material. */
    lists = glGenLists(2);
    glNewList(lists, GL_COMPILE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red_plastic);
    sphere(1.0, 8, 6);
    glEndList();
    glNewList(lists + 1, GL_COMPILE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, gold);
    torus(0.3, 1.2, 6, 8);
    glEndList();

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);

    glFeedbackBuffer(FEEDBACK_SIZE, GL_4D_COLOR_TEXTURE, feedback);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(1.0f);
    glPushMatrix();
    glTranslatef(-1.5f, 0.0f, 0.0f);
    glCallList(lists);
    glPopMatrix();
    glPassThrough(2.0f);
    /* A change bracketed by the attribute stack: a dimmer light 0 and no texture. */
    glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, light1_diffuse);
    glPushMatrix();
    glTranslatef(1.5f, 0.0f, 0.0f);
    glRotatef(60.0f, 0.0f, 1.0f, 0.0f);
    glCallList(lists + 1);
    glPopMatrix();
    glPopAttrib();
    glPassThrough(3.0f);
    /* The same torus after the pop: light 1 and the white light 0 again. */
    glPushMatrix();
    glTranslatef(0.0f, -1.5f, -1.0f);
    glCallList(lists + 1);
    glPopMatrix();
    print_feedback("scene", glRenderMode(GL_RENDER));
    printf("scene error %d\n", (int)glGetError());
    glDeleteLists(lists, 2);
    glDeleteTextures(1, &texture);
    return 0;
}
