/* A legacy-style OpenGL 1.x program: a lit sphere of points under three lights (directional,
 * attenuated point light, spot light), two materials and color material, read back through
 * feedback. It includes only <GL/gl.h>: `make demo` links it once against libfflight and once
 * against OSMesa (-DUSE_OSMESA) and prints the two results side by side. */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#ifdef USE_OSMESA
#include <GL/osmesa.h>
#endif

#define RINGS 8
#define SEGMENTS 12
#define MAX_VALUES (RINGS * SEGMENTS * 2 * 8 + 16)

static void setup_lights(void)
{
    static const GLfloat sun_dir[4] = {0.3f, 1.0f, 0.5f, 0.0f};
    static const GLfloat sun_color[4] = {0.9f, 0.85f, 0.7f, 1.0f};
    static const GLfloat lamp_pos[4] = {-2.0f, 0.5f, 1.5f, 1.0f};
    static const GLfloat lamp_color[4] = {0.2f, 0.4f, 1.0f, 1.0f};
    static const GLfloat spot_pos[4] = {0.0f, 3.0f, 0.0f, 1.0f};
    static const GLfloat spot_dir[3] = {0.0f, -1.0f, 0.0f};
    static const GLfloat spot_color[4] = {1.0f, 0.3f, 0.2f, 1.0f};
    static const GLfloat scene_ambient[4] = {0.1f, 0.1f, 0.12f, 1.0f};

    glEnable(GL_LIGHTING);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, scene_ambient);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);

    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, sun_dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, sun_color);
    glLightfv(GL_LIGHT0, GL_SPECULAR, sun_color);

    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_POSITION, lamp_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, lamp_color);
    glLightfv(GL_LIGHT1, GL_SPECULAR, lamp_color);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.3f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);

    glEnable(GL_LIGHT2);
    glLightfv(GL_LIGHT2, GL_POSITION, spot_pos);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, spot_dir);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, spot_color);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 35.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8.0f);
}

static void setup_material(void)
{
    static const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
}

static void draw_sphere(void)
{
    int ring, segment;
    glBegin(GL_POINTS);
    for (ring = 0; ring < RINGS; ring++) {
        double theta = M_PI * (ring + 0.5) / RINGS;
        for (segment = 0; segment < SEGMENTS; segment++) {
            double phi = 2.0 * M_PI * segment / SEGMENTS;
            GLfloat x = (GLfloat)(sin(theta) * cos(phi));
            GLfloat y = (GLfloat)cos(theta);
            GLfloat z = (GLfloat)(sin(theta) * sin(phi));
            glColor3f(0.5f + 0.5f * x, 0.6f, 0.5f + 0.5f * z);
            glNormal3f(2.0f * x, 2.0f * y, 2.0f * z); /* GL_NORMALIZE fixes the length */
            glVertex3f(x, y, z);
        }
    }
    glEnd();
}

int main(void)
{
    static GLfloat feedback[MAX_VALUES];
    GLint count, i;
#ifdef USE_OSMESA
    static GLubyte pixels[256 * 256 * 4];
    OSMesaContext osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!osmesa || !OSMesaMakeCurrent(osmesa, pixels, GL_UNSIGNED_BYTE, 256, 256)) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
#endif
    glViewport(0, 0, 256, 256);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    setup_lights();
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glScalef(1.0f, 1.3f, 1.0f);
    setup_material();

    glFeedbackBuffer(MAX_VALUES, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    draw_sphere();
    count = glRenderMode(GL_RENDER);
    if (count < 0) {
        fprintf(stderr, "feedback overflowed\n");
        return 1;
    }
    /* GL_POINT_TOKEN, x, y, z, r, g, b, a per point */
    for (i = 0; i + 8 <= count; i += 8)
        printf("%.2f %.2f  %.6f %.6f %.6f %.6f\n", feedback[i + 1], feedback[i + 2],
               feedback[i + 4], feedback[i + 5], feedback[i + 6], feedback[i + 7]);
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error\n");
        return 1;
    }
    return 0;
}
