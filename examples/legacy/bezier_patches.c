/*
 * A classic evaluator program in the style of the Red Book's bezsurf.c: bicubic Bezier
 * patches (a wavy lid in four patches, mirrored like the teapot's) defined with glMap2f,
 * lit with GL_AUTO_NORMAL, drawn as a grid of points with glMapGrid2f/glEvalMesh2 and as
 * triangles of glEvalCoord2f, in feedback mode. Written against the system <GL/gl.h> only;
 * it runs unchanged against fflight and against OSMesa (with -DFFL_OSMESA, which only adds
 * a context), and c_tests/legacy_bezier_patches.c compares the two.
 */
#include <GL/gl.h>
#include <stdio.h>
#ifdef FFL_OSMESA
#include <GL/osmesa.h>
#endif

#define FEEDBACK_SIZE 16384

static GLfloat feedback[FEEDBACK_SIZE];

/* One quarter of the lid: 4 x 4 control points, u along x and v along y. */
static GLfloat quarter[4][4][3];

static void make_quarter(void)
{
    static const float heights[4][4] = {
        { 1.2f, 1.2f, 1.0f, 0.6f },
        { 1.2f, 1.5f, 1.1f, 0.5f },
        { 1.0f, 1.1f, 0.8f, 0.3f },
        { 0.6f, 0.5f, 0.3f, 0.0f },
    };
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            quarter[i][j][0] = (float)i * 0.5f;
            quarter[i][j][1] = (float)j * 0.5f;
            quarter[i][j][2] = heights[i][j];
        }
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
        } else {
            printf("%s unexpected token %d\n", tag, (int)token);
            return;
        }
        printf("%s %s %d\n", tag, token == GL_POINT_TOKEN ? "point" : "polygon", count);
        for (k = 0; k < count && i + 7 <= n; k++, i += 7)
            printf("%s  v xyz %.9g %.9g %.9g rgba %.9g %.9g %.9g %.9g\n", tag, feedback[i],
                   feedback[i + 1], feedback[i + 2], feedback[i + 3], feedback[i + 4],
                   feedback[i + 5], feedback[i + 6]);
    }
}

int main(void)
{
    static const GLfloat light_position[4] = { 1.0f, 1.0f, 3.0f, 0.0f };
    static const GLfloat ambient[4] = { 0.2f, 0.2f, 0.2f, 1.0f };
    static const GLfloat copper[4] = { 0.8f, 0.45f, 0.25f, 1.0f };
    static const GLfloat white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    int q;
#ifdef FFL_OSMESA
    static GLubyte color_buffer[128 * 128 * 4];
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (context == NULL || !OSMesaMakeCurrent(context, color_buffer, GL_UNSIGNED_BYTE, 128, 128))
        return 1;
#endif
    make_quarter();
    glViewport(0, 0, 128, 128);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, copper);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 50.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);

    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &quarter[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(6, 0.0f, 1.0f, 6, 0.0f, 1.0f);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.5, 2.5, -2.5, 2.5, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);

    glFeedbackBuffer(FEEDBACK_SIZE, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    /* The four quarters, mirrored as the teapot's patches are. */
    for (q = 0; q < 4; q++) {
        glPushMatrix();
        glScalef(q & 1 ? -1.0f : 1.0f, q & 2 ? -1.0f : 1.0f, 1.0f);
        glEvalMesh2(GL_POINT, 0, 6, 0, 6);
        glPopMatrix();
    }
    print_feedback("lid_points", glRenderMode(GL_RENDER));

    /* One quarter as triangles of evaluated points. */
    glFeedbackBuffer(FEEDBACK_SIZE, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_TRIANGLES);
    for (q = 0; q < 3; q++) {
        float u = (float)q / 3.0f, v = (float)(2 - q) / 3.0f;
        glEvalCoord2f(u, v);
        glEvalCoord2f(u + 1.0f / 3.0f, v);
        glEvalCoord2f(u, v + 1.0f / 3.0f);
    }
    glEnd();
    print_feedback("lid_triangles", glRenderMode(GL_RENDER));
    printf("lid error %d\n", (int)glGetError());
    return 0;
}
