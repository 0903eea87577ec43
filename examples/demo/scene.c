/* A legacy-style OpenGL 1.x program: a lit sphere (quad strips, color material) on a lit
 * floor (quads) under three lights (directional, attenuated point light, spot light), back
 * faces culled, read back through feedback. It includes only <GL/gl.h>: `make demo` links it
 * once against libfflight and once against OSMesa (-DUSE_OSMESA), compares the two outputs
 * and draws both (examples/demo/compare.py).
 *
 * Output: `viewport W H`, then for each polygon fed back, a line `polygon N`, then N lines `x y z r g b a` (window
 * coordinates and the lit color of each vertex). */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#ifdef USE_OSMESA
#include <GL/osmesa.h>
#endif

#define RINGS 16
#define SEGMENTS 32
#define FLOOR_TILES 12
#define SIZE 320
/* At most two triangles a quad, each at most 2 + 9 * 7 values after clipping (it is not). */
#define MAX_VALUES ((RINGS * SEGMENTS + FLOOR_TILES * FLOOR_TILES) * 2 * (2 + 9 * 7))

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

static void sphere_vertex(int ring, int segment)
{
    double theta = M_PI * ring / RINGS;
    double phi = 2.0 * M_PI * segment / SEGMENTS;
    GLfloat x = (GLfloat)(sin(theta) * cos(phi));
    GLfloat y = (GLfloat)cos(theta);
    GLfloat z = (GLfloat)(sin(theta) * sin(phi));
    glColor3f(0.5f + 0.5f * x, 0.6f, 0.5f + 0.5f * z);
    glNormal3f(2.0f * x, 2.0f * y, 2.0f * z); /* GL_NORMALIZE fixes the length */
    glVertex3f(x, y, z);
}

static void draw_sphere(void)
{
    int ring, segment;
    for (ring = 0; ring < RINGS; ring++) {
        glBegin(GL_QUAD_STRIP);
        for (segment = 0; segment <= SEGMENTS; segment++) {
            sphere_vertex(ring + 1, segment);
            sphere_vertex(ring, segment);
        }
        glEnd();
    }
}

/* A floor of tiles in two colors under the sphere, facing up. */
static void draw_floor(void)
{
    const GLfloat extent = 3.0f, y = -1.5f, tile = 2.0f * extent / FLOOR_TILES;
    int i, j;
    glNormal3f(0.0f, 1.0f, 0.0f);
    glBegin(GL_QUADS);
    for (i = 0; i < FLOOR_TILES; i++) {
        for (j = 0; j < FLOOR_TILES; j++) {
            GLfloat x0 = -extent + i * tile, z0 = -extent + j * tile;
            if ((i + j) % 2)
                glColor3f(0.8f, 0.8f, 0.75f);
            else
                glColor3f(0.35f, 0.4f, 0.5f);
            glVertex3f(x0, y, z0);
            glVertex3f(x0, y, z0 + tile);
            glVertex3f(x0 + tile, y, z0 + tile);
            glVertex3f(x0 + tile, y, z0);
        }
    }
    glEnd();
}

int main(void)
{
    static GLfloat feedback[MAX_VALUES];
    GLint count, i;
#ifdef USE_OSMESA
    static GLubyte pixels[SIZE * SIZE * 4];
    OSMesaContext osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!osmesa || !OSMesaMakeCurrent(osmesa, pixels, GL_UNSIGNED_BYTE, SIZE, SIZE)) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
#endif
    glViewport(0, 0, SIZE, SIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -5.0f);
    setup_lights();
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    setup_material();
    glEnable(GL_CULL_FACE);

    glFeedbackBuffer(MAX_VALUES, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    draw_floor();
    glPushMatrix();
    glScalef(1.0f, 1.3f, 1.0f);
    draw_sphere();
    glPopMatrix();
    count = glRenderMode(GL_RENDER);
    if (count < 0) {
        fprintf(stderr, "feedback overflowed\n");
        return 1;
    }
    printf("viewport %d %d\n", SIZE, SIZE);
    /* GL_POLYGON_TOKEN, n, then x y z r g b a for each of the n vertices */
    for (i = 0; i < count;) {
        GLint n, k;
        if (feedback[i] != GL_POLYGON_TOKEN) {
            fprintf(stderr, "unexpected feedback token %g\n", feedback[i]);
            return 1;
        }
        n = (GLint)feedback[i + 1];
        printf("polygon %d\n", (int)n);
        for (k = 0, i += 2; k < n; k++, i += 7)
            printf("%.9g %.9g %.9g  %.9g %.9g %.9g %.9g\n", feedback[i], feedback[i + 1],
                   feedback[i + 2], feedback[i + 3], feedback[i + 4], feedback[i + 5],
                   feedback[i + 6]);
    }
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error\n");
        return 1;
    }
    return 0;
}
