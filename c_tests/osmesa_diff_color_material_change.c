/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: the materials GL_COLOR_MATERIAL gives the current color, at its
 * glEnable and when glColorMaterial changes the tracked property before anything is drawn.
 * Found by the differential sequence fuzzer (tests/osmesa_fuzz.rs, seeds 242, 2280, 2898).
 *
 * §2.14.3: "ColorMaterial ... When COLOR_MATERIAL is enabled, the indicated parameter(s) of
 * the material(s) track the current color"; a property tracked while the current color was
 * c keeps c when the tracking moves to another property (nothing restores it). So after
 * glEnable(GL_COLOR_MATERIAL) (GL_AMBIENT_AND_DIFFUSE), glColor4f(c) and
 * glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR), the ambient and diffuse colors are c.
 * Mesa copies the current color into the tracked materials when it flushes its vertex
 * state, and some paths flush the color without the materials: then glColorMaterial's own
 * update goes to the new property only, and the old ones never receive c. Measured: a
 * glGetFloatv between glColor and glColorMaterial, or a glLightModel before glColor, loses
 * c (the materials keep (0.2, 0.2, 0.2, 1) and (0.8, 0.8, 0.8, 1)), and so does a glColor
 * before glEnable(GL_COLOR_MATERIAL): the spec gives the tracked properties the current
 * color at the glEnable, OSMesa only at the next glColor; with nothing between,
 * a glGetFloatv before glColor, a glGetError after it, tracking moved to GL_FRONT only, or a
 * glColor after the glEnable, OSMesa agrees with the spec (controls).
 *
 * Here: lighting on, no light, scene ambient (1, 1, 1, 1), so a point's color is the front
 * ambient color (alpha: the diffuse alpha); c = (0.5, 0.25, 0.75, 0.6).
 */
#include "ffl_test.h"

static void show(const char *name, const GLfloat *ambient, const GLfloat *diffuse)
{
    GLfloat buffer[16], got[4];
    GLint n;
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, got);
    printf("%s", name);
    ffl_pfv("ambient", got, 4);
    printf(" ref");
    ffl_pfv("ambient", ambient, 4);
    printf("\n");
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, got);
    printf("%s", name);
    ffl_pfv("diffuse", got, 4);
    printf(" ref");
    ffl_pfv("diffuse", diffuse, 4);
    printf("\n");
    glFeedbackBuffer(16, GL_3D_COLOR, buffer);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glEnd();
    n = glRenderMode(GL_RENDER);
    printf("%s values %d", name, (int)n);
    ffl_pfv("rgba", buffer + 4, 3);
    ffl_pfv("a", buffer + 7, 1);
    printf(" ref");
    ffl_pfv("rgba", ambient, 3);
    ffl_pfv("a", diffuse + 3, 1);
    printf("\n");
}

static void setup(void)
{
    static const GLfloat white[4] = { 1, 1, 1, 1 };
    static const GLfloat ambient[4] = { 0.2f, 0.2f, 0.2f, 1 };
    static const GLfloat diffuse[4] = { 0.8f, 0.8f, 0.8f, 1 };
    glDisable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glColor4fv(white);
}

int main(void)
{
    static const GLfloat c[4] = { 0.5f, 0.25f, 0.75f, 0.6f };
    static const GLfloat white[4] = { 1, 1, 1, 1 };
    GLfloat scratch[4];

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glEnable(GL_LIGHTING);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);

    /* Nothing between: both libraries agree. */
    setup();
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(c);
    glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
    show("direct", c, c);

    /* A query between glColor and glColorMaterial. */
    setup();
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(c);
    glGetFloatv(GL_CURRENT_COLOR, scratch);
    glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
    show("query_after_color", c, c);

    /* A query between glEnable and glColor (the fuzzer's sequence). */
    setup();
    glEnable(GL_COLOR_MATERIAL);
    glGetFloatv(GL_CURRENT_COLOR, scratch);
    glColor4fv(c);
    glColorMaterial(GL_FRONT, GL_SPECULAR);
    show("query_before_color", c, c);

    /* glGetError between glColor and glColorMaterial (what the fuzzer does after each call). */
    setup();
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(c);
    (void)glGetError();
    glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
    show("get_error_after_color", c, c);
    /* The fuzzer's seed 242: a glLightModel before glColor. */
    setup();
    glEnable(GL_COLOR_MATERIAL);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glColor4fv(c);
    glColorMaterial(GL_FRONT, GL_SPECULAR);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    show("separate_specular", c, c);

    setup();
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(c);
    glColorMaterial(GL_FRONT, GL_SPECULAR);
    show("front_only", c, c);
    /* glEnable(GL_COLOR_MATERIAL) with the current color given before it: the tracked
     * properties take that color at once (the fuzzer's seeds 2280 and 2898). */
    setup();
    glColor4fv(c);
    glEnable(GL_COLOR_MATERIAL);
    show("enable_after_color", c, c);

    /* The same with a glColor after the glEnable: both agree (control). */
    setup();
    glColor4fv(white);
    glEnable(GL_COLOR_MATERIAL);
    glColor4fv(c);
    show("color_after_enable", c, c);
    ffl_print_error("error");
    return 0;
}
