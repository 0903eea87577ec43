/* One program, two GL libraries: OSMesa (a real GL, which exports glLightfv, glBegin, ...) and
 * fflight's prefixed static library (libfflight_prefixed.a, which exports the same commands as
 * ffl_glLightfv, ffl_glBegin, ...). Each library gets different lighting; each call must reach
 * the library it names: each keeps its own state, its own error flag and feeds back its own
 * lit color, and the dynamic linker finds glLightfv in libOSMesa and ffl_glLightfv in this
 * program. Prints one line per check; the exit status is the number of failed checks.
 * Built and run by tests/prefixed.rs. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "fflight_prefixed.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures;

static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAILED", what);
    failures += !ok;
}

static int near4(const GLfloat *got, const GLfloat *want)
{
    int i;
    for (i = 0; i < 4; i++)
        if (fabsf(got[i] - want[i]) > 1e-5f)
            return 0;
    return 1;
}

/* The file that defines a function, as the dynamic linker sees it. */
static const char *defined_in(void (*function)(void))
{
    Dl_info info;
    void *address;
    memcpy(&address, &function, sizeof address);
    if (!dladdr(address, &info) || !info.dli_fname)
        return "";
    return info.dli_fname;
}

int main(void)
{
    static GLubyte pixels[64 * 64 * 4];
    static const GLfloat red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1};
    static const GLfloat position[4] = {0, 0, 1, 0};
    /* default material (ambient 0.2, diffuse 0.8) and scene ambient 0.2: 0.04 + 0.8 * light */
    static const GLfloat lit_red[4] = {0.84f, 0.04f, 0.04f, 1}, lit_green[4] = {0.04f, 0.84f, 0.04f, 1};
    GLfloat osmesa_feedback[16], fflight_feedback[16], value[4];
    GLint osmesa_count, fflight_count;
    void (*osmesa_light)(void), (*fflight_light)(void);
    OSMesaContext osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);

    if (!osmesa || !OSMesaMakeCurrent(osmesa, pixels, GL_UNSIGNED_BYTE, 64, 64)) {
        printf("FAILED: no OSMesa context\n");
        return 1;
    }

    /* The same commands on both, with a red light for OSMesa and a green one for fflight. */
    glViewport(0, 0, 64, 64);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, red);
    ffl_glViewport(0, 0, 64, 64);
    ffl_glEnable(GL_LIGHTING);
    ffl_glEnable(GL_LIGHT0);
    ffl_glLightfv(GL_LIGHT0, GL_POSITION, position);
    ffl_glLightfv(GL_LIGHT0, GL_DIFFUSE, green);
    /* State set on one library only. */
    glEnable(GL_LIGHT1);
    ffl_glEnable(GL_NORMALIZE);

    glGetLightfv(GL_LIGHT0, GL_DIFFUSE, value);
    check(near4(value, red), "OSMesa keeps its red light");
    ffl_glGetLightfv(GL_LIGHT0, GL_DIFFUSE, value);
    check(near4(value, green), "fflight keeps its green light");
    check(glIsEnabled(GL_LIGHT1) && !ffl_glIsEnabled(GL_LIGHT1), "GL_LIGHT1 is on in OSMesa only");
    check(!glIsEnabled(GL_NORMALIZE) && ffl_glIsEnabled(GL_NORMALIZE),
          "GL_NORMALIZE is on in fflight only");

    /* One lit point fed back by each library. */
    glFeedbackBuffer(16, GL_3D_COLOR, osmesa_feedback);
    ffl_glFeedbackBuffer(16, GL_3D_COLOR, fflight_feedback);
    glRenderMode(GL_FEEDBACK);
    ffl_glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    ffl_glBegin(GL_POINTS);
    glNormal3f(0, 0, 1);
    ffl_glNormal3f(0, 0, 1);
    glVertex3f(0, 0, 0);
    ffl_glVertex3f(0, 0, 0);
    glEnd();
    ffl_glEnd();
    osmesa_count = glRenderMode(GL_RENDER);
    fflight_count = ffl_glRenderMode(GL_RENDER);
    printf("OSMesa feedback:  %d values, color %.6f %.6f %.6f %.6f\n", osmesa_count,
           osmesa_feedback[4], osmesa_feedback[5], osmesa_feedback[6], osmesa_feedback[7]);
    printf("fflight feedback: %d values, color %.6f %.6f %.6f %.6f\n", fflight_count,
           fflight_feedback[4], fflight_feedback[5], fflight_feedback[6], fflight_feedback[7]);
    check(osmesa_count == 8 && osmesa_feedback[0] == GL_POINT_TOKEN &&
              near4(osmesa_feedback + 4, lit_red),
          "OSMesa feeds back its point lit red");
    check(fflight_count == 8 && fflight_feedback[0] == GL_POINT_TOKEN &&
              near4(fflight_feedback + 4, lit_green),
          "fflight feeds back its point lit green");

    /* Each error flag sees only its own library's errors. */
    ffl_glEnable(0x1234);
    check(glGetError() == GL_NO_ERROR, "OSMesa has no error after fflight's bad call");
    check(ffl_glGetError() == GL_INVALID_ENUM, "fflight has GL_INVALID_ENUM");
    glEnable(0x1234);
    check(ffl_glGetError() == GL_NO_ERROR, "fflight has no error after OSMesa's bad call");
    check(glGetError() == GL_INVALID_ENUM, "OSMesa has GL_INVALID_ENUM");

    /* Where the dynamic linker found each. */
    osmesa_light = (void (*)(void))glLightfv;
    fflight_light = (void (*)(void))ffl_glLightfv;
    printf("glLightfv is in %s\n", defined_in(osmesa_light));
    check(strstr(defined_in(osmesa_light), "libOSMesa") != NULL, "glLightfv is libOSMesa's");
    check(strstr(defined_in(fflight_light), "libOSMesa") == NULL, "ffl_glLightfv is not libOSMesa's");

    OSMesaDestroyContext(osmesa);
    return failures;
}
