/* ffl-test: differential */
/*
 * Compiled against the system <GL/gl.h> only (not fflight.h, not
 * ffl_test.h): a program written for any OpenGL 1.x implementation links
 * against libfflight unchanged and gets the same results as OSMesa.
 * Lights a few points (three lights, one a spot light, materials, color
 * material) and reads them back through feedback as GL_3D_COLOR and
 * GL_4D_COLOR_TEXTURE.
 */
#include <GL/gl.h>
#ifdef FFL_OSMESA
#include <GL/osmesa.h>
#endif
#include <stddef.h>
#include <stdio.h>

static void print_value(GLfloat v)
{
    double d = v;
    if (d == 0.0)
        d = 0.0; /* no -0 */
    printf(" %.9g", d);
}

/* Prints the buffer: one line per point, labelled values. */
static int print_points(const char *tag, const GLfloat *buf, GLint n, int four_d)
{
    int per_vertex = four_d ? 12 : 7, i = 0, k;
    printf("%s count %d\n", tag, (int)n);
    while (i < n) {
        if (buf[i] != (GLfloat)GL_POINT_TOKEN || i + 1 + per_vertex > n) {
            printf("%s unexpected_token\n", tag);
            return 1;
        }
        i++;
        printf("%s point %s", tag, four_d ? "xyzw" : "xyz");
        for (k = 0; k < (four_d ? 4 : 3); k++)
            print_value(buf[i++]);
        printf(" rgba");
        for (k = 0; k < 4; k++)
            print_value(buf[i++]);
        if (four_d) {
            printf(" strq");
            for (k = 0; k < 4; k++)
                print_value(buf[i++]);
        }
        printf("\n");
    }
    return 0;
}

static void draw(void)
{
    static const GLfloat points[6][3] = {
        { 0, 0, 0 }, { 2, 1, -1 }, { -3, 2, 1 }, { 1, -2, 3 }, { 4, 4, -4 }, { -1, -1, -6 },
    };
    int k;
    glBegin(GL_POINTS);
    for (k = 0; k < 6; k++) {
        glNormal3f(0.3f * (float)k - 0.5f, 0.5f, 0.8f);
        glColor4f(0.1f + 0.1f * (float)k, 0.4f, 0.5f - 0.05f * (float)k, 0.9f);
        glTexCoord4f((float)k, 0.5f, -1.0f, 1.0f);
        glVertex3fv(points[k]);
    }
    glEnd();
}

int main(void)
{
    static const GLfloat light0_pos[4] = { 1, 2, 3, 0 };
    static const GLfloat light1_pos[4] = { -4, 3, 6, 1 };
    static const GLfloat light2_pos[4] = { 0, 0, 8, 1 };
    static const GLfloat spot_dir[3] = { 0, 0, -1 };
    static const GLfloat grey[4] = { 0.3f, 0.3f, 0.3f, 1 };
    static const GLfloat warm[4] = { 0.6f, 0.4f, 0.2f, 1 };
    static const GLfloat cool[4] = { 0.2f, 0.3f, 0.7f, 1 };
    static const GLfloat spec[4] = { 0.5f, 0.5f, 0.5f, 1 };
    static const GLfloat emission[4] = { 0.05f, 0.0f, 0.1f, 1 };
    GLfloat buf[6 * 13 + 4];
    GLint n;
    int failed = 0;
#ifdef FFL_OSMESA
    static GLubyte pixels[64 * 64 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (ctx == NULL || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 64, 64))
        return 2;
#endif

    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 2, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -15);
    glRotatef(20, 1, 1, 0);

    glLightfv(GL_LIGHT0, GL_POSITION, light0_pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, grey);
    glLightfv(GL_LIGHT0, GL_SPECULAR, grey);
    glLightfv(GL_LIGHT1, GL_POSITION, light1_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    glLightfv(GL_LIGHT2, GL_POSITION, light2_pos);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 30);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 4);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, cool);
    glLightfv(GL_LIGHT2, GL_AMBIENT, grey);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHT2);

    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 16);
    glMaterialfv(GL_FRONT, GL_EMISSION, emission);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);

    glFeedbackBuffer((GLsizei)(sizeof buf / sizeof buf[0]), GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    n = glRenderMode(GL_RENDER);
    failed |= print_points("3d_color", buf, n, 0);

    glFeedbackBuffer((GLsizei)(sizeof buf / sizeof buf[0]), GL_4D_COLOR_TEXTURE, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    n = glRenderMode(GL_RENDER);
    failed |= print_points("4d_color_texture", buf, n, 1);

    printf("error %d\n", (int)glGetError());
    return failed;
}
