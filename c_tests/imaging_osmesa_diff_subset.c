/* ffl-test: osmesa-diff */
/*
 * The imaging subset of GL 1.5 (§3.6.2-3.6.3, §6.1.7-6.1.9), which <GL/gl.h> declares and
 * Mesa 22 no longer implements (OSMesa answers GL_INVALID_OPERATION or GL_INVALID_ENUM:
 * docs/osmesa-differences.md, 21). Checked against this program's own expectations:
 * color tables (entries scaled, biased and clamped, sub-tables, copies of the empty
 * framebuffer, proxies, parameters, widths that are not powers of two, GL_TABLE_TOO_LARGE),
 * convolution filters (1D, 2D, separable, parameters, the maximum size), histogram and
 * minmax (formats, sinks, resets; nothing is drawn, so the counts stay 0) and their enables,
 * the color matrix stack and the post-convolution and post-color-matrix transfer modes.
 */
#include "ffl_test.h"
#include <float.h>

static void error(const char *what, GLenum expected)
{
    GLenum e = glGetError();
    printf("%s error %d ref error %d\n", what, (int)e, (int)expected);
}

static void ints(const char *what, const GLint *got, const GLint *expected, int n)
{
    int k;
    printf("%s i", what);
    for (k = 0; k < n; k++)
        printf(" %d", (int)got[k]);
    printf(" ref i");
    for (k = 0; k < n; k++)
        printf(" %d", (int)expected[k]);
    printf("\n");
}

static void floats4(const char *what, const GLfloat *got, double a, double b, double c, double d)
{
    printf("%s", what);
    ffl_pfv("v", got, 4);
    printf(" ref v %.9g %.9g %.9g %.9g\n", a, b, c, d);
}

static void color_tables(void)
{
    static const GLubyte table[4][4] = {
        { 0, 64, 130, 255 }, { 255, 0, 0, 255 }, { 10, 20, 30, 40 }, { 200, 100, 50, 0 },
    };
    static const GLfloat scale[4] = { 2.0f, 0.5f, 1.0f, 1.0f };
    static const GLfloat bias[4] = { 0.0f, 0.25f, -0.25f, 0.0f };
    GLubyte back[16];
    GLint v[4], expected[4];
    GLfloat f[4];

    glColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_SCALE, scale);
    glColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_BIAS, bias);
    glColorTable(GL_COLOR_TABLE, GL_RGBA8, 4, GL_RGBA, GL_UNSIGNED_BYTE, table);
    error("color table", GL_NO_ERROR);
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, v);
    expected[0] = 4;
    ints("width", v, expected, 1);
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_FORMAT, v);
    expected[0] = GL_RGBA8;
    ints("format", v, expected, 1);
    glGetColorTableParameteriv(GL_COLOR_TABLE, GL_COLOR_TABLE_RED_SIZE, v);
    expected[0] = 8;
    ints("red size", v, expected, 1);
    glGetColorTableParameterfv(GL_COLOR_TABLE, GL_COLOR_TABLE_BIAS, f);
    floats4("bias", f, 0, 0.25, -0.25, 0);
    glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, back);
    /* Entry 0: r 0*2, g 64/255*0.5+0.25, b 130/255-0.25, a 1; entry 1 r clamped to 1. */
    {
        GLint got[8], want[8];
        int k;
        for (k = 0; k < 8; k++)
            got[k] = back[k];
        want[0] = 0;
        want[1] = (GLint)floor((64.0 / 255.0 * 0.5 + 0.25) * 255.0 + 0.5);
        want[2] = (GLint)floor((130.0 / 255.0 - 0.25) * 255.0 + 0.5);
        want[3] = 255;
        want[4] = 255;
        want[5] = 64;
        want[6] = 0;
        want[7] = 255;
        ints("entries 0 1", got, want, 8);
    }
    /* A sub-table and a copy of the (empty) framebuffer. */
    glColorSubTable(GL_COLOR_TABLE, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, table[1]);
    glCopyColorSubTable(GL_COLOR_TABLE, 2, 0, 0, 1);
    glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, back);
    {
        GLint got[8], want[8] = { 0, 64, 0, 0, 255, 64, 0, 255 };
        int k;
        for (k = 0; k < 8; k++)
            got[k] = back[8 + k];
        ints("entries 2 3", got, want, 8);
    }
    error("sub tables", GL_NO_ERROR);
    glColorSubTable(GL_COLOR_TABLE, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, table[1]);
    error("sub table past the end", GL_INVALID_VALUE);
    glColorTable(GL_COLOR_TABLE, GL_RGBA8, 3, GL_RGBA, GL_UNSIGNED_BYTE, table);
    error("width 3", GL_INVALID_VALUE);
    glColorTable(GL_COLOR_TABLE, GL_DEPTH_COMPONENT, 4, GL_RGBA, GL_UNSIGNED_BYTE, table);
    error("depth format", GL_INVALID_ENUM);
    glColorTable(GL_TEXTURE_2D, GL_RGBA, 4, GL_RGBA, GL_UNSIGNED_BYTE, table);
    error("bad target", GL_INVALID_ENUM);
    glColorTable(GL_COLOR_TABLE, GL_RGBA, 1024, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    error("too large", GL_TABLE_TOO_LARGE);
    glColorTable(GL_PROXY_COLOR_TABLE, GL_LUMINANCE8, 1024, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, v);
    expected[0] = 0;
    ints("proxy too large width", v, expected, 1);
    glColorTable(GL_PROXY_POST_CONVOLUTION_COLOR_TABLE, GL_LUMINANCE8, 16, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
    glGetColorTableParameteriv(GL_PROXY_POST_CONVOLUTION_COLOR_TABLE,
                               GL_COLOR_TABLE_LUMINANCE_SIZE, v);
    expected[0] = 8;
    ints("proxy luminance size", v, expected, 1);
    error("proxies", GL_NO_ERROR);
    glCopyColorTable(GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_RGB, 0, 0, 2);
    glGetColorTableParameteriv(GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, v);
    expected[0] = 2;
    ints("copied width", v, expected, 1);
}

static void convolution(void)
{
    static const GLfloat kernel[3][3][4] = {
        { { 0.1f, 0, 0, 1 }, { 0.2f, 0, 0, 1 }, { 0.3f, 0, 0, 1 } },
        { { 0.4f, 0, 0, 1 }, { 0.5f, 0, 0, 1 }, { 0.6f, 0, 0, 1 } },
        { { 0.7f, 0, 0, 1 }, { 0.8f, 0, 0, 1 }, { 0.9f, 0, 0, 1 } },
    };
    static const GLfloat scale[4] = { 0.5f, 1, 1, 1 };
    GLfloat back[9 * 4], f[4];
    GLint v[2], expected[2];
    glConvolutionParameterfv(GL_CONVOLUTION_2D, GL_CONVOLUTION_FILTER_SCALE, scale);
    glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_RGBA16, 3, 3, GL_RGBA, GL_FLOAT, kernel);
    error("filter 2d", GL_NO_ERROR);
    glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_CONVOLUTION_WIDTH, v);
    glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_CONVOLUTION_HEIGHT, v + 1);
    expected[0] = expected[1] = 3;
    ints("filter size", v, expected, 2);
    glGetConvolutionFilter(GL_CONVOLUTION_2D, GL_RGBA, GL_FLOAT, back);
    floats4("filter entry 4", back + 16, 0.25, 0, 0, 1);
    glConvolutionParameteri(GL_CONVOLUTION_1D, GL_CONVOLUTION_BORDER_MODE, GL_REPLICATE_BORDER);
    glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_BORDER_MODE, v);
    expected[0] = GL_REPLICATE_BORDER;
    ints("border mode", v, expected, 1);
    glConvolutionParameterf(GL_CONVOLUTION_1D, GL_CONVOLUTION_FILTER_SCALE, 2.0f);
    error("scalar vector pname", GL_INVALID_ENUM);
    glConvolutionFilter1D(GL_CONVOLUTION_1D, GL_LUMINANCE, 10, GL_LUMINANCE, GL_FLOAT, back);
    error("width 10", GL_INVALID_VALUE);
    glSeparableFilter2D(GL_SEPARABLE_2D, GL_RGB16, 3, 2, GL_RGBA, GL_FLOAT, kernel[0], kernel[1]);
    glGetSeparableFilter(GL_SEPARABLE_2D, GL_RGBA, GL_FLOAT, back, back + 12, NULL);
    floats4("separable column 1", back + 16, 0.5, 0, 0, 1);
    glCopyConvolutionFilter1D(GL_CONVOLUTION_1D, GL_RGBA, 0, 0, 4);
    glGetConvolutionParameteriv(GL_CONVOLUTION_1D, GL_CONVOLUTION_WIDTH, v);
    expected[0] = 4;
    ints("copied filter width", v, expected, 1);
    glGetConvolutionParameterfv(GL_CONVOLUTION_2D, GL_CONVOLUTION_FILTER_SCALE, f);
    floats4("filter scale", f, 0.5, 1, 1, 1);
    error("convolution", GL_NO_ERROR);
}

static void histogram_minmax(void)
{
    GLuint counts[8];
    GLfloat extremes[8];
    GLint v[1], expected[1];
    GLboolean sink = GL_FALSE;
    int k;
    glHistogram(GL_HISTOGRAM, 8, GL_RGB, GL_TRUE);
    glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_WIDTH, v);
    expected[0] = 8;
    ints("histogram width", v, expected, 1);
    glGetHistogramParameteriv(GL_HISTOGRAM, GL_HISTOGRAM_SINK, v);
    expected[0] = 1;
    ints("histogram sink", v, expected, 1);
    for (k = 0; k < 8; k++)
        counts[k] = 7;
    glGetHistogram(GL_HISTOGRAM, GL_TRUE, GL_RED, GL_UNSIGNED_INT, counts);
    printf("histogram counts i %u %u ref i 0 0\n", counts[0], counts[7]);
    glHistogram(GL_HISTOGRAM, 8, GL_INTENSITY, GL_FALSE);
    error("intensity histogram", GL_INVALID_ENUM);
    glHistogram(GL_HISTOGRAM, 6, GL_RGB, GL_FALSE);
    error("histogram width 6", GL_INVALID_VALUE);
    glMinmax(GL_MINMAX, GL_LUMINANCE_ALPHA, GL_FALSE);
    glGetMinmaxParameteriv(GL_MINMAX, GL_MINMAX_FORMAT, v);
    expected[0] = GL_LUMINANCE_ALPHA;
    ints("minmax format", v, expected, 1);
    glResetMinmax(GL_MINMAX);
    glGetMinmax(GL_MINMAX, GL_FALSE, GL_RGBA, GL_FLOAT, extremes);
    printf("minmax reset v %g %g ref v %g %g\n", (double)extremes[0], (double)extremes[4],
           (double)FLT_MAX, -(double)FLT_MAX);
    glGetBooleanv(GL_MINMAX, &sink);
    printf("minmax enabled b %d ref b 0\n", (int)sink);
    glEnable(GL_HISTOGRAM);
    glEnable(GL_SEPARABLE_2D);
    printf("enabled b %d %d ref b 1 1\n", (int)glIsEnabled(GL_HISTOGRAM),
           (int)glIsEnabled(GL_SEPARABLE_2D));
    glPushAttrib(GL_PIXEL_MODE_BIT);
    glDisable(GL_HISTOGRAM);
    glPopAttrib();
    printf("restored b %d ref b 1\n", (int)glIsEnabled(GL_HISTOGRAM));
    error("histogram minmax", GL_NO_ERROR);
}

/* The color matrix stack and the post-convolution and post-color-matrix transfer modes. */
static void color_matrix(void)
{
    GLfloat m[16];
    GLint v[2], expected[2];
    glMatrixMode(GL_COLOR);
    error("color matrix mode", GL_NO_ERROR);
    glPushMatrix();
    glScalef(0.5f, 2.0f, 1.0f);
    glGetFloatv(GL_COLOR_MATRIX, m);
    floats4("color matrix diagonal", (GLfloat[4]){ m[0], m[5], m[10], m[15] }, 0.5, 2, 1, 1);
    glGetIntegerv(GL_COLOR_MATRIX_STACK_DEPTH, v);
    glGetIntegerv(GL_MATRIX_MODE, v + 1);
    expected[0] = 2;
    expected[1] = GL_COLOR;
    ints("color stack depth, mode", v, expected, 2);
    glPopMatrix();
    glPopMatrix();
    error("color stack underflow", GL_STACK_UNDERFLOW);
    glGetIntegerv(GL_MAX_COLOR_MATRIX_STACK_DEPTH, v);
    printf("max color stack depth at least 2 b %d ref b 1\n", v[0] >= 2);
    glMatrixMode(GL_MODELVIEW);
    glPixelTransferf(GL_POST_COLOR_MATRIX_GREEN_SCALE, 0.75f);
    glPixelTransferf(GL_POST_CONVOLUTION_ALPHA_BIAS, -0.5f);
    glGetFloatv(GL_POST_COLOR_MATRIX_GREEN_SCALE, m);
    glGetFloatv(GL_POST_CONVOLUTION_ALPHA_BIAS, m + 1);
    glGetFloatv(GL_POST_CONVOLUTION_RED_SCALE, m + 2);
    glGetFloatv(GL_POST_COLOR_MATRIX_BLUE_BIAS, m + 3);
    floats4("post transfer", m, 0.75, -0.5, 1, 0);
    glPushAttrib(GL_PIXEL_MODE_BIT);
    glPixelTransferf(GL_POST_COLOR_MATRIX_GREEN_SCALE, 3.0f);
    glPopAttrib();
    glGetFloatv(GL_POST_COLOR_MATRIX_GREEN_SCALE, m);
    printf("post transfer restored v %g ref v 0.75\n", (double)m[0]);
    error("color matrix", GL_NO_ERROR);
}

int main(void)
{
    ffl_test_init();
    color_tables();
    convolution();
    histogram_minmax();
    color_matrix();
    return 0;
}
