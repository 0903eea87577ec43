/* ffl-test: differential */
/*
 * The fog and hint attribute groups (§3.10, §5.6; tables 6.10, 6.27): initial values,
 * every glFog form, glHint for every target, the errors (after which the state must be
 * unchanged) and GL_INVALID_OPERATION between glBegin and glEnd.
 * Not tried here (see osmesa_diff_buffers_and_factors.c): glFogf/glFogi with GL_FOG_COLOR,
 * which fflight rejects as its other scalar commands with a vector pname and Mesa accepts.
 */
#include "ffl_test.h"

static void print_fog(const char *what)
{
    printf("%s\n", what);
    ffl_print_floats(" color", GL_FOG_COLOR, 4);
    ffl_print_floats(" index", GL_FOG_INDEX, 1);
    ffl_print_floats(" density", GL_FOG_DENSITY, 1);
    ffl_print_floats(" start", GL_FOG_START, 1);
    ffl_print_floats(" end", GL_FOG_END, 1);
    ffl_print_ints(" mode", GL_FOG_MODE, 1);
    ffl_print_ints(" coord_src", GL_FOG_COORD_SRC, 1);
    ffl_print_bools(" fog", GL_FOG, 1, 1);
    ffl_print_bools(" color_sum", GL_COLOR_SUM, 1, 1);
}

static const GLenum targets[7] = {
    GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT, GL_TEXTURE_COMPRESSION_HINT
};

static void print_hints(const char *what)
{
    int i;
    printf("%s\n", what);
    for (i = 0; i < 7; i++) {
        printf(" target %d", i);
        ffl_print_ints("", targets[i], 1);
    }
}

int main(void)
{
    static const GLfloat color[4] = { 0.25f, 1.5f, -0.5f, 0.75f };
    static const GLint icolor[4] = { 2147483647, 0, -2147483647 - 1, 1073741823 };
    GLfloat v = 0.5f;
    GLint iv = GL_EXP2;
    int i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    print_fog("fog_initial");
    print_hints("hints_initial");
    ffl_print_error("initial_queries");

    glFogfv(GL_FOG_COLOR, color);
    glFogf(GL_FOG_DENSITY, 0.5f);
    glFogi(GL_FOG_START, -3);
    glFogfv(GL_FOG_END, &v);
    glFogf(GL_FOG_INDEX, 4.0f);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glEnable(GL_FOG);
    glEnable(GL_COLOR_SUM);
    print_fog("fog_set");
    glFogiv(GL_FOG_COLOR, icolor);
    glFogiv(GL_FOG_MODE, &iv);
    print_fog("fog_set_integers");
    for (i = 0; i < 7; i++)
        glHint(targets[i], i % 2 ? GL_NICEST : GL_FASTEST);
    print_hints("hints_set");
    ffl_print_error("sets");

    /* errors */
    glFogf(GL_FOG_DENSITY, -1.0f);
    ffl_print_error("fog_density_negative");
    glFogi(GL_FOG_MODE, GL_LINEAR + 1);
    ffl_print_error("fog_mode_bad");
    glFogi(GL_FOG_COORD_SRC, GL_FOG);
    ffl_print_error("fog_coord_src_bad");
    glFogf(GL_FOG_HINT, 1.0f);
    ffl_print_error("fog_bad_pname");
    glFogfv(GL_FOG_MODE + 0x100, color);
    ffl_print_error("fogv_bad_pname");
    glHint(GL_FOG, GL_NICEST);
    ffl_print_error("hint_bad_target");
    glHint(GL_FOG_HINT, GL_FOG);
    ffl_print_error("hint_bad_mode");
    glBegin(GL_POINTS);
    glFogf(GL_FOG_START, 9.0f);
    glEnd();
    ffl_print_error("fog_inside_begin_end");
    glBegin(GL_POINTS);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    glEnd();
    ffl_print_error("hint_inside_begin_end");
    print_fog("fog_after_errors");
    print_hints("hints_after_errors");
    ffl_print_error("end");
    return 0;
}
