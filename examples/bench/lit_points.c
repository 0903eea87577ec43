/* Benchmark: lights points with 8 local lights (attenuation, spots, local viewer, two-sided
 * color material) and reads them back through feedback, in glBegin/glEnd batches. Built
 * against fflight and against OSMesa (-DUSE_OSMESA) by `make bench`, which prints the ratio.
 * Prints the median of several timed runs, in lit vertices per second. */
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#ifdef USE_OSMESA
#include <GL/osmesa.h>
#endif

#define BATCH 4096
#define BATCHES 64
#define RUNS 7

static GLfloat feedback[BATCH * 8 + 16];

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void setup(void)
{
    int i;
    glViewport(0, 0, 256, 256);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2, 2, -2, 2, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    for (i = 0; i < 8; i++) {
        GLfloat position[4] = {(GLfloat)(i % 3) - 1.0f, (GLfloat)(i % 2), 2.0f, 1.0f};
        GLfloat color[4] = {0.2f + 0.1f * (GLfloat)i, 0.5f, 0.9f - 0.1f * (GLfloat)i, 1.0f};
        GLfloat direction[3] = {0.0f, 0.0f, -1.0f};
        glEnable(GL_LIGHT0 + i);
        glLightfv(GL_LIGHT0 + i, GL_POSITION, position);
        glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, color);
        glLightfv(GL_LIGHT0 + i, GL_SPECULAR, color);
        glLightf(GL_LIGHT0 + i, GL_LINEAR_ATTENUATION, 0.2f);
        if (i % 2) {
            glLightfv(GL_LIGHT0 + i, GL_SPOT_DIRECTION, direction);
            glLightf(GL_LIGHT0 + i, GL_SPOT_CUTOFF, 60.0f);
            glLightf(GL_LIGHT0 + i, GL_SPOT_EXPONENT, 4.0f);
        }
    }
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32.0f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
}

static double run(void)
{
    int b, i;
    double start = now();
    for (b = 0; b < BATCHES; b++) {
        glFeedbackBuffer(BATCH * 8 + 16, GL_3D_COLOR, feedback);
        glRenderMode(GL_FEEDBACK);
        glBegin(GL_POINTS);
        for (i = 0; i < BATCH; i++) {
            GLfloat x = (GLfloat)(i % 64) / 32.0f - 1.0f, y = (GLfloat)(i / 64) / 32.0f - 1.0f;
            glColor3f(0.5f + 0.5f * x, 0.5f, 0.5f - 0.5f * y);
            glNormal3f(x, y, 1.0f);
            glVertex3f(x, y, 0.1f * x * y);
        }
        glEnd();
        if (glRenderMode(GL_RENDER) != BATCH * 8) {
            fprintf(stderr, "unexpected feedback count\n");
            exit(1);
        }
    }
    return (double)(BATCH * BATCHES) / (now() - start);
}

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    double rates[RUNS];
    int r;
#ifdef USE_OSMESA
    static GLubyte pixels[256 * 256 * 4];
    OSMesaContext osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!osmesa || !OSMesaMakeCurrent(osmesa, pixels, GL_UNSIGNED_BYTE, 256, 256))
        return 1;
#endif
    setup();
    run(); /* warm-up: OSMesa compiles its vertex program here */
    for (r = 0; r < RUNS; r++)
        rates[r] = run();
    qsort(rates, RUNS, sizeof rates[0], compare);
    printf("%.0f\n", rates[RUNS / 2]);
    return 0;
}
