/* ffl-test: differential */
/*
 * GL errors (§2.5 and the command descriptions): after each bad call the
 * program prints the error glGetError returns, and where it matters the
 * state that must be unchanged. The first error is kept until glGetError
 * reads it. Checks follow Mesa's order (light number, then pname, then
 * value), which is what makes the same bad call give the same error.
 * Not tested: a vector pname through a scalar call (glLightf(l, GL_AMBIENT,
 * x)): Mesa accepts it and zero-fills, the spec does not say.
 */
#include "ffl_test.h"

static void print_light_float(const char *what, GLenum light, GLenum pname)
{
    GLfloat v[4] = { -9, -9, -9, -9 };
    glGetLightfv(light, pname, v);
    printf("%s", what);
    ffl_pfv("val", v, 1);
    printf("\n");
}

int main(void)
{
    static const GLfloat color[4] = { 0.5f, 0.25f, 0.125f, 1 };
    GLfloat buf[64], v[4];
    GLint depth = 0, i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    ffl_print_error("fresh_context");

    /* feedback: never established */
    glRenderMode(GL_FEEDBACK);
    ffl_print_error("render_mode_feedback_without_buffer");
    glRenderMode(GL_RENDER);
    glGetError();

    /* lights */
    glLightfv(GL_LIGHT0 + 8, GL_AMBIENT, color);
    ffl_print_error("light_number_8");
    glLightfv(0x1234, GL_AMBIENT, color);
    ffl_print_error("light_bad_enum");
    glLightfv(GL_LIGHT0, 0x1234, color);
    ffl_print_error("light_bad_pname");
    glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 500);
    ffl_print_error("light_bad_number_and_value");
    glLightf(GL_LIGHT0, 0x1234, -1);
    ffl_print_error("light_bad_pname_and_value");
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 12);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128.5f);
    ffl_print_error("spot_exponent_128.5");
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, -0.5f);
    ffl_print_error("spot_exponent_negative");
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 128);
    ffl_print_error("spot_exponent_128");
    print_light_float("spot_exponent_after", GL_LIGHT1, GL_SPOT_EXPONENT);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 90.5f);
    ffl_print_error("spot_cutoff_90.5");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 179);
    ffl_print_error("spot_cutoff_179");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, -1);
    ffl_print_error("spot_cutoff_negative");
    print_light_float("spot_cutoff_after", GL_LIGHT1, GL_SPOT_CUTOFF);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180);
    ffl_print_error("spot_cutoff_180");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 0);
    ffl_print_error("spot_cutoff_0");
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, -0.25f);
    ffl_print_error("constant_attenuation_negative");
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, -1);
    ffl_print_error("linear_attenuation_negative");
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, -2);
    ffl_print_error("quadratic_attenuation_negative");
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0);
    ffl_print_error("quadratic_attenuation_0");
    print_light_float("constant_attenuation_after", GL_LIGHT1, GL_CONSTANT_ATTENUATION);
    glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, v);
    ffl_print_error("get_light_number_8");
    glGetLightfv(GL_LIGHT0, GL_SHININESS, v);
    ffl_print_error("get_light_bad_pname");

    /* materials */
    glMaterialfv(0x0406 /* GL_LEFT: an enum that names no face */, GL_AMBIENT, color);
    ffl_print_error("material_bad_face");
    glMaterialfv(GL_FRONT, GL_POSITION, color);
    ffl_print_error("material_bad_pname");
    glMaterialf(GL_FRONT, GL_SHININESS, 10);
    glMaterialf(GL_FRONT, GL_SHININESS, 128.5f);
    ffl_print_error("shininess_128.5");
    glMaterialf(GL_FRONT, GL_SHININESS, -1);
    ffl_print_error("shininess_negative");
    glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
    printf("shininess_after");
    ffl_pfv("val", v, 1);
    printf("\n");
    glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v);
    ffl_print_error("get_material_front_and_back");
    glGetMaterialfv(GL_FRONT, GL_SPOT_CUTOFF, v);
    ffl_print_error("get_material_bad_pname");

    /* light model, color material, enables */
    glLightModeli(0x1234, 0);
    ffl_print_error("light_model_bad_pname");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT);
    ffl_print_error("color_control_bad_value");
    glColorMaterial(GL_FRONT, GL_SHININESS);
    ffl_print_error("color_material_bad_mode");
    glColorMaterial(0x0406 /* GL_LEFT */, GL_DIFFUSE);
    ffl_print_error("color_material_bad_face");
    glEnable(0x1234);
    ffl_print_error("enable_bad_cap");
    glDisable(GL_LIGHT0 + 8);
    ffl_print_error("disable_light_8");

    /* first error sticks */
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 200);
    glLightfv(GL_LIGHT0 + 9, GL_AMBIENT, color);
    ffl_print_error("first_of_two");
    ffl_print_error("then");

    /* begin/end */
    glBegin(0x1234);
    ffl_print_error("begin_bad_mode");
    glEnd();
    ffl_print_error("end_without_begin");
    glBegin(GL_POINTS);
    glBegin(GL_POINTS);
    glEnd();
    ffl_print_error("nested_begin");
    glBegin(GL_POINTS);
    glLightfv(GL_LIGHT0, GL_AMBIENT, color);
    glEnd();
    ffl_print_error("light_inside_begin");
    glBegin(GL_POINTS);
    glMaterialfv(GL_FRONT, GL_AMBIENT, color);
    glNormal3f(0, 1, 0);
    glColor4f(1, 0, 0, 1);
    glTexCoord2f(0, 1);
    glEnd();
    ffl_print_error("allowed_inside_begin");
    glBegin(GL_POINTS);
    glEnable(GL_LIGHTING);
    glEnd();
    ffl_print_error("enable_inside_begin");
    printf("lighting_after %d\n", (int)glIsEnabled(GL_LIGHTING));
    glBegin(GL_POINTS);
    glFeedbackBuffer(64, GL_3D, buf);
    glEnd();
    ffl_print_error("feedback_buffer_inside_begin");

    /* feedback */
    glFeedbackBuffer(-1, GL_3D, buf);
    ffl_print_error("feedback_negative_size");
    glFeedbackBuffer(64, 0x1234, buf);
    ffl_print_error("feedback_bad_type");
    glFeedbackBuffer(64, GL_3D, buf);
    ffl_print_error("feedback_ok");
    glRenderMode(GL_FEEDBACK);
    glFeedbackBuffer(64, GL_3D, buf);
    ffl_print_error("feedback_buffer_in_feedback_mode");
    glRenderMode(GL_RENDER);
    glRenderMode(0x1234);
    ffl_print_error("render_mode_bad");

    /* matrices */
    glMatrixMode(0x1234);
    ffl_print_error("matrix_mode_bad");
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    ffl_print_error("pop_empty_modelview");
    glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &depth);
    printf("max_modelview_depth_at_least_32 %d\n", depth >= 32);
    for (i = 1; i < depth; i++)
        glPushMatrix();
    ffl_print_error("push_to_max");
    glPushMatrix();
    ffl_print_error("push_past_max");
    for (i = 1; i < depth; i++)
        glPopMatrix();
    ffl_print_error("pop_back");
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    ffl_print_error("pop_empty_projection");
    glMatrixMode(GL_MODELVIEW);

    /* viewport */
    glViewport(0, 0, -1, 10);
    ffl_print_error("viewport_negative_width");
    glViewport(0, 0, 10, -1);
    ffl_print_error("viewport_negative_height");
    ffl_print_error("finally");
    return 0;
}
