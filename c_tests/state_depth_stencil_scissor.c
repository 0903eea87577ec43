/* ffl-test: differential */
/*
 * The depth, stencil and scissor attribute groups and the alpha test (§4.1.2-4.1.6,
 * §4.2.2, §4.2.3; tables 6.19, 6.20): initial values, values set and read back through
 * glGet and glIsEnabled, and the errors, after which the state must be unchanged.
 * Not printed: the initial scissor box (the window's size in OSMesa, 0 0 0 0 in fflight,
 * which has no window).
 */
#include "ffl_test.h"

static void print_stencil(const char *what)
{
    printf("%s\n", what);
    ffl_print_ints(" func", GL_STENCIL_FUNC, 1);
    ffl_print_ints(" value_mask", GL_STENCIL_VALUE_MASK, 1);
    ffl_print_ints(" reference", GL_STENCIL_REF, 1);
    ffl_print_ints(" fail", GL_STENCIL_FAIL, 1);
    ffl_print_ints(" zfail", GL_STENCIL_PASS_DEPTH_FAIL, 1);
    ffl_print_ints(" zpass", GL_STENCIL_PASS_DEPTH_PASS, 1);
    ffl_print_ints(" writemask", GL_STENCIL_WRITEMASK, 1);
    ffl_print_ints(" clear", GL_STENCIL_CLEAR_VALUE, 1);
    ffl_print_bools(" test", GL_STENCIL_TEST, 1, 1);
}

static void print_depth(const char *what)
{
    printf("%s\n", what);
    ffl_print_ints(" func", GL_DEPTH_FUNC, 1);
    ffl_print_bools(" writemask", GL_DEPTH_WRITEMASK, 1, 0);
    ffl_print_floats(" clear", GL_DEPTH_CLEAR_VALUE, 1);
    ffl_print_bools(" test", GL_DEPTH_TEST, 1, 1);
}

static void print_alpha_and_scissor(const char *what)
{
    printf("%s\n", what);
    ffl_print_ints(" alpha_func", GL_ALPHA_TEST_FUNC, 1);
    ffl_print_floats(" alpha_reference", GL_ALPHA_TEST_REF, 1);
    ffl_print_bools(" alpha_test", GL_ALPHA_TEST, 1, 1);
    ffl_print_ints(" scissor_box", GL_SCISSOR_BOX, 4);
    ffl_print_bools(" scissor_test", GL_SCISSOR_TEST, 1, 1);
}

int main(void)
{
    ffl_test_init();
    glViewport(0, 0, 64, 64);

    ffl_print_ints("stencil_bits", GL_STENCIL_BITS, 1);
    print_stencil("stencil_initial");
    print_depth("depth_initial");
    printf("alpha_initial\n");
    ffl_print_ints(" alpha_func", GL_ALPHA_TEST_FUNC, 1);
    ffl_print_floats(" alpha_reference", GL_ALPHA_TEST_REF, 1);
    ffl_print_bools(" alpha_test", GL_ALPHA_TEST, 1, 1);
    ffl_print_bools(" scissor_test", GL_SCISSOR_TEST, 1, 1);
    ffl_print_error("initial_queries");

    /* set and read back */
    glStencilFunc(GL_GEQUAL, 1000, 0xF0F0u);
    glStencilOp(GL_INCR_WRAP, GL_DECR, GL_INVERT);
    glStencilMask(0x3Cu);
    glClearStencil(77);
    glEnable(GL_STENCIL_TEST);
    print_stencil("stencil_set");
    glStencilFunc(GL_LESS, -5, 0xFFFFFFFFu);
    ffl_print_ints("stencil_reference_negative", GL_STENCIL_REF, 1);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glClearDepth(0.25);
    glEnable(GL_DEPTH_TEST);
    print_depth("depth_set");
    glClearDepth(7.0);
    ffl_print_floats("clear_depth_clamped", GL_DEPTH_CLEAR_VALUE, 1);
    glAlphaFunc(GL_NOTEQUAL, 0.375f);
    glEnable(GL_ALPHA_TEST);
    glScissor(-3, 5, 20, 30);
    glEnable(GL_SCISSOR_TEST);
    print_alpha_and_scissor("alpha_scissor_set");
    glAlphaFunc(GL_LESS, 1.5f);
    ffl_print_floats("alpha_reference_clamped", GL_ALPHA_TEST_REF, 1);
    glAlphaFunc(GL_GEQUAL, 0.375f);
    ffl_print_error("sets");

    /* errors: the state must stay as it is */
    glStencilFunc(GL_ALWAYS + 1, 3, 3);
    ffl_print_error("stencil_func_bad");
    glStencilOp(GL_KEEP, GL_ONE, GL_KEEP);
    ffl_print_error("stencil_op_bad_zfail");
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP + 1);
    ffl_print_error("stencil_op_bad_zpass");
    glDepthFunc(GL_NEVER - 1);
    ffl_print_error("depth_func_bad");
    glAlphaFunc(GL_LESS + 0x100, 0.5f);
    ffl_print_error("alpha_func_bad");
    glScissor(0, 0, -1, 4);
    ffl_print_error("scissor_negative_width");
    glScissor(0, 0, 4, -1);
    ffl_print_error("scissor_negative_height");
    glClear(GL_DEPTH_BUFFER_BIT | 0x1);
    ffl_print_error("clear_bad_mask");
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    ffl_print_error("clear_good_mask");

    /* between glBegin and glEnd */
    glBegin(GL_POINTS);
    glDepthFunc(GL_ALWAYS);
    glEnd();
    ffl_print_error("depth_func_inside_begin_end");
    glBegin(GL_POINTS);
    glStencilFunc(GL_NEVER, 0, 0);
    glEnd();
    ffl_print_error("stencil_func_inside_begin_end");
    glBegin(GL_POINTS);
    glScissor(1, 1, 1, 1);
    glEnd();
    ffl_print_error("scissor_inside_begin_end");
    glBegin(GL_POINTS);
    glClearStencil(1);
    glEnd();
    ffl_print_error("clear_stencil_inside_begin_end");
    glBegin(GL_POINTS);
    glEnable(GL_DEPTH_TEST);
    glEnd();
    ffl_print_error("enable_inside_begin_end");

    print_stencil("stencil_after_errors");
    print_depth("depth_after_errors");
    print_alpha_and_scissor("alpha_scissor_after_errors");
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    ffl_print_bools("disabled_depth", GL_DEPTH_TEST, 1, 1);
    ffl_print_bools("disabled_stencil", GL_STENCIL_TEST, 1, 1);
    ffl_print_error("end");
    return 0;
}
