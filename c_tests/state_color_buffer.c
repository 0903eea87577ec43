/* ffl-test: differential */
/*
 * The color-buffer and accumulation-buffer attribute groups, glAccum without an
 * accumulation buffer (§4.1.8-4.1.10, §4.2;
 * tables 6.19, 6.20): blending, logic op, dithering, the draw and read buffers, the write
 * masks and clear values. Initial values, values set and read back, the errors (after
 * which the state must be unchanged), GL_INVALID_OPERATION between glBegin and glEnd.
 * Not tried here (see osmesa_diff_buffers_and_factors.c): GL_SRC_ALPHA_SATURATE as a
 * destination factor, the back buffer of a single-buffered framebuffer, and
 * glReadBuffer(GL_FRONT_AND_BACK), which GL 1.5 rejects and Mesa accepts; a fractional
 * clear index, which GL keeps to an unspecified precision (Mesa: none); auxiliary buffers.
 */
#include "ffl_test.h"

static void print_color_buffer(const char *what)
{
    printf("%s\n", what);
    ffl_print_ints(" blend_src", GL_BLEND_SRC, 1);
    ffl_print_ints(" blend_dst", GL_BLEND_DST, 1);
    ffl_print_ints(" blend_src_rgb", GL_BLEND_SRC_RGB, 1);
    ffl_print_ints(" blend_dst_rgb", GL_BLEND_DST_RGB, 1);
    ffl_print_ints(" blend_src_alpha", GL_BLEND_SRC_ALPHA, 1);
    ffl_print_ints(" blend_dst_alpha", GL_BLEND_DST_ALPHA, 1);
    ffl_print_ints(" blend_equation", GL_BLEND_EQUATION, 1);
    ffl_print_floats(" blend_color", GL_BLEND_COLOR, 4);
    ffl_print_bools(" blend", GL_BLEND, 1, 1);
    ffl_print_ints(" logic_op_mode", GL_LOGIC_OP_MODE, 1);
    ffl_print_bools(" color_logic_op", GL_COLOR_LOGIC_OP, 1, 1);
    ffl_print_bools(" index_logic_op", GL_INDEX_LOGIC_OP, 1, 1);
    ffl_print_bools(" dither", GL_DITHER, 1, 1);
    ffl_print_ints(" draw_buffer", GL_DRAW_BUFFER, 1);
    ffl_print_ints(" read_buffer", GL_READ_BUFFER, 1);
    ffl_print_bools(" color_writemask", GL_COLOR_WRITEMASK, 4, 0);
    ffl_print_ints(" index_writemask", GL_INDEX_WRITEMASK, 1);
    ffl_print_floats(" color_clear", GL_COLOR_CLEAR_VALUE, 4);
    ffl_print_floats(" index_clear", GL_INDEX_CLEAR_VALUE, 1);
    ffl_print_floats(" accum_clear", GL_ACCUM_CLEAR_VALUE, 4);
}

int main(void)
{
    ffl_test_init();
    glViewport(0, 0, 64, 64);

    ffl_print_bools("doublebuffer", GL_DOUBLEBUFFER, 1, 0);
    ffl_print_bools("stereo", GL_STEREO, 1, 0);
    ffl_print_bools("multisample", GL_MULTISAMPLE, 1, 1);
    ffl_print_ints("accum_bits", GL_ACCUM_RED_BITS, 1);
    ffl_print_ints("accum_alpha_bits", GL_ACCUM_ALPHA_BITS, 1);
    print_color_buffer("initial");
    ffl_print_error("initial_queries");

    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    print_color_buffer("blend_func");
    glBlendFuncSeparate(GL_DST_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE,
                        GL_CONSTANT_ALPHA);
    glBlendColor(0.25f, -1.0f, 2.0f, 0.5f);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glEnable(GL_BLEND);
    glLogicOp(GL_NAND);
    glEnable(GL_COLOR_LOGIC_OP);
    glDisable(GL_DITHER);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_FRONT_LEFT);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glIndexMask(0x0Fu);
    glClearColor(0.5f, 2.0f, -0.5f, 0.25f);
    glClearIndex(3.0f);
    glClearAccum(-2.0f, 0.5f, 1.5f, -0.25f);
    print_color_buffer("set");
    ffl_print_error("sets");
    glDrawBuffer(GL_FRONT_AND_BACK);
    ffl_print_ints("draw_buffer_front_and_back", GL_DRAW_BUFFER, 1);
    glDrawBuffer(GL_LEFT);
    ffl_print_ints("draw_buffer_left", GL_DRAW_BUFFER, 1);
    glEnable(GL_INDEX_LOGIC_OP);
    ffl_print_bools("index_logic_op", GL_INDEX_LOGIC_OP, 1, 1);
    glBlendEquation(GL_MIN);
    ffl_print_ints("blend_equation_min", GL_BLEND_EQUATION, 1);

    /* errors */
    glBlendFunc(GL_SRC_ALPHA_SATURATE + 1, GL_ZERO);
    ffl_print_error("blend_func_bad_src");
    glBlendFunc(GL_ONE, GL_FUNC_ADD);
    ffl_print_error("blend_func_bad_dst");
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_LINE);
    ffl_print_error("blend_func_separate_bad_dst_alpha");
    glBlendEquation(GL_ONE);
    ffl_print_error("blend_equation_bad");
    glLogicOp(GL_SET + 1);
    ffl_print_error("logic_op_bad");
    glDrawBuffer(GL_BACK_RIGHT);
    ffl_print_error("draw_buffer_back_right_missing");
    glDrawBuffer(GL_DEPTH_TEST);
    ffl_print_error("draw_buffer_bad_enum");
    glReadBuffer(GL_DEPTH_TEST);
    ffl_print_error("read_buffer_bad_enum");
    glAccum(GL_ADD + 1, 1.0f);
    ffl_print_error("accum_bad_op");
    glAccum(GL_LOAD, 1.0f);
    ffl_print_error("accum_no_accumulation_buffer");
    glBegin(GL_POINTS);
    glAccum(GL_ACCUM, 0.5f);
    glEnd();
    ffl_print_error("accum_inside_begin_end");
    glBegin(GL_POINTS);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnd();
    ffl_print_error("blend_func_inside_begin_end");
    glBegin(GL_POINTS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnd();
    ffl_print_error("color_mask_inside_begin_end");
    glBegin(GL_POINTS);
    glClearColor(1, 1, 1, 1);
    glEnd();
    ffl_print_error("clear_color_inside_begin_end");
    glBegin(GL_POINTS);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnd();
    ffl_print_error("clear_inside_begin_end");
    glBegin(GL_POINTS);
    glDrawBuffer(GL_FRONT);
    glEnd();
    ffl_print_error("draw_buffer_inside_begin_end");
    print_color_buffer("after_errors");
    ffl_print_error("end");
    return 0;
}
