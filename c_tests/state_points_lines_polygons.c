/* ffl-test: differential */
/*
 * The point, line, polygon and polygon-stipple attribute groups (§3.3-3.5; table 6.13):
 * glPointSize, glPointParameter*, glLineWidth, glLineStipple, glPolygonOffset,
 * glSampleCoverage and the multisample enables (§3.2.1, §4.1.3),
 * glPolygonStipple and glGetPolygonStipple (through the pixel store modes, §3.6.4,
 * §4.3.2), their enables; the errors (after which the state must be unchanged) and
 * GL_INVALID_OPERATION between glBegin and glEnd.
 * Not printed: GL_POINT_SIZE_MAX's initial value and the size ranges, which are the
 * implementation's largest point size (Mesa's llvmpipe: 255; fflight: 1024).
 */
#include "ffl_test.h"

static void print_raster(const char *what)
{
    printf("%s\n", what);
    ffl_print_floats(" point_size", GL_POINT_SIZE, 1);
    ffl_print_floats(" point_size_min", GL_POINT_SIZE_MIN, 1);
    ffl_print_floats(" point_fade", GL_POINT_FADE_THRESHOLD_SIZE, 1);
    ffl_print_floats(" point_attenuation", GL_POINT_DISTANCE_ATTENUATION, 3);
    ffl_print_bools(" point_smooth", GL_POINT_SMOOTH, 1, 1);
    ffl_print_floats(" line_width", GL_LINE_WIDTH, 1);
    ffl_print_ints(" line_stipple_pattern", GL_LINE_STIPPLE_PATTERN, 1);
    ffl_print_ints(" line_stipple_repeat", GL_LINE_STIPPLE_REPEAT, 1);
    ffl_print_bools(" line_smooth", GL_LINE_SMOOTH, 1, 1);
    ffl_print_bools(" line_stipple", GL_LINE_STIPPLE, 1, 1);
    ffl_print_floats(" offset_factor", GL_POLYGON_OFFSET_FACTOR, 1);
    ffl_print_floats(" offset_units", GL_POLYGON_OFFSET_UNITS, 1);
    ffl_print_bools(" offset_point", GL_POLYGON_OFFSET_POINT, 1, 1);
    ffl_print_bools(" offset_line", GL_POLYGON_OFFSET_LINE, 1, 1);
    ffl_print_bools(" offset_fill", GL_POLYGON_OFFSET_FILL, 1, 1);
    ffl_print_bools(" polygon_smooth", GL_POLYGON_SMOOTH, 1, 1);
    ffl_print_bools(" polygon_stipple", GL_POLYGON_STIPPLE, 1, 1);
    ffl_print_bools(" multisample", GL_MULTISAMPLE, 1, 1);
    ffl_print_bools(" sample_alpha_to_coverage", GL_SAMPLE_ALPHA_TO_COVERAGE, 1, 1);
    ffl_print_bools(" sample_alpha_to_one", GL_SAMPLE_ALPHA_TO_ONE, 1, 1);
    ffl_print_bools(" sample_coverage", GL_SAMPLE_COVERAGE, 1, 1);
    ffl_print_floats(" sample_coverage_value", GL_SAMPLE_COVERAGE_VALUE, 1);
    ffl_print_bools(" sample_coverage_invert", GL_SAMPLE_COVERAGE_INVERT, 1, 0);
}

/* Prints the stipple as glGetPolygonStipple packs it into `n` bytes that start as 0xAA. */
static void print_stipple(const char *what, int n)
{
    GLubyte bytes[400];
    int i;
    memset(bytes, 0xAA, sizeof bytes);
    glGetPolygonStipple(bytes);
    printf("%s i", what);
    for (i = 0; i < n; i++)
        printf(" %d", bytes[i]);
    printf("\n");
}

int main(void)
{
    static const GLfloat attenuation[3] = { 0.5f, 0.25f, 0.125f };
    static const GLint iattenuation[3] = { 1, 2, 3 };
    GLubyte pattern[128], memory[400];
    GLint i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    print_raster("initial");
    print_stipple("stipple_initial", 128);
    ffl_print_error("initial_queries");

    glPointSize(3.5f);
    glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
    glPointParameteri(GL_POINT_SIZE_MAX, 40);
    ffl_print_floats("point_size_max", GL_POINT_SIZE_MAX, 1);
    glPointParameterfv(GL_POINT_FADE_THRESHOLD_SIZE, attenuation);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
    glEnable(GL_POINT_SMOOTH);
    glLineWidth(2.5f);
    glLineStipple(3, 0xF0F0);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_LINE_STIPPLE);
    glPolygonOffset(1.5f, -2.0f);
    glEnable(GL_POLYGON_OFFSET_POINT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_POLYGON_SMOOTH);
    glEnable(GL_POLYGON_STIPPLE);
    glDisable(GL_MULTISAMPLE);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.25f, GL_TRUE);
    print_raster("set");
    glSampleCoverage(1.5f, GL_FALSE);
    ffl_print_floats("sample_coverage_value_clamped", GL_SAMPLE_COVERAGE_VALUE, 1);
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, iattenuation);
    ffl_print_floats("point_attenuation_integers", GL_POINT_DISTANCE_ATTENUATION, 3);
    glLineStipple(1000, 0x1234);
    ffl_print_ints("line_stipple_repeat_clamped_high", GL_LINE_STIPPLE_REPEAT, 1);
    glLineStipple(-4, 0x1234);
    ffl_print_ints("line_stipple_repeat_clamped_low", GL_LINE_STIPPLE_REPEAT, 1);
    ffl_print_error("sets");

    /* the stipple: default modes, then LSB first, row length, skips and alignment */
    for (i = 0; i < 128; i++)
        pattern[i] = (GLubyte)(i * 37 + 11);
    glPolygonStipple(pattern);
    print_stipple("stipple_default", 128);
    glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
    print_stipple("stipple_pack_lsb_first", 128);
    glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_PACK_ROW_LENGTH, 48);
    glPixelStorei(GL_PACK_SKIP_ROWS, 2);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    print_stipple("stipple_pack_rows", 8 * 34);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    memset(memory, 0, sizeof memory);
    for (i = 0; i < 32; i++)
        memcpy(memory + 6 + i * 6 + 1, pattern + 4 * (31 - i), 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 48);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 8);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glPolygonStipple(memory);
    print_stipple("stipple_unpacked_with_modes", 128);
    ffl_print_error("stipples");

    /* errors */
    glPointSize(0.0f);
    ffl_print_error("point_size_zero");
    glPointSize(-1.0f);
    ffl_print_error("point_size_negative");
    glLineWidth(0.0f);
    ffl_print_error("line_width_zero");
    glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
    ffl_print_error("point_size_min_negative");
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -0.5f);
    ffl_print_error("point_fade_negative");
    glPointParameterf(GL_POINT_SIZE, 1.0f);
    ffl_print_error("point_parameter_bad_pname");
    glBegin(GL_POINTS);
    glPointSize(5.0f);
    glEnd();
    ffl_print_error("point_size_inside_begin_end");
    glBegin(GL_POINTS);
    glLineStipple(2, 0xFF00);
    glEnd();
    ffl_print_error("line_stipple_inside_begin_end");
    glBegin(GL_POINTS);
    glPolygonOffset(0.0f, 0.0f);
    glEnd();
    ffl_print_error("polygon_offset_inside_begin_end");
    glBegin(GL_POINTS);
    glPolygonStipple(pattern);
    glEnd();
    ffl_print_error("polygon_stipple_inside_begin_end");
    glBegin(GL_POINTS);
    glSampleCoverage(0.5f, GL_TRUE);
    glEnd();
    ffl_print_error("sample_coverage_inside_begin_end");
    print_raster("after_errors");
    print_stipple("stipple_after_errors", 128);
    ffl_print_error("end");
    return 0;
}
