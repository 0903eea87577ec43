/* ffl-test: differential */
/*
 * Texture objects, parameters, environments and units (§2.7, §3.8.4, §3.8.12, §3.8.13,
 * §6.1.3): names, binding (creation, another target's object), deletion reverting bindings,
 * residency and priorities; every glTexParameter and glTexEnv pname set in each form and read
 * back in both; the texture enables and bindings per unit; and the errors, after which the
 * state must be unchanged. Not compared: the implementation limits (GL_MAX_*); OSMesa's
 * extensions (GL_ZERO / GL_ONE combiner sources, units past GL_TEXTURE7); glTexEnvf of
 * GL_TEXTURE_ENV_COLOR, where Mesa reads four values from the scalar's address; a name
 * glGenTextures returned but no bind used (texture_osmesa_diff_unbound_names.c).
 */
#include "ffl_test.h"

static const GLenum tex_pnames[14] = {
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
    GL_TEXTURE_WRAP_R, GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY, GL_TEXTURE_MIN_LOD,
    GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_GENERATE_MIPMAP,
    GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE
};

static const GLenum env_pnames[17] = {
    GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB, GL_COMBINE_ALPHA,
    GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB, GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA,
    GL_SOURCE2_ALPHA, GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB, GL_OPERAND0_ALPHA,
    GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA, GL_RGB_SCALE
};

static void print_params(const char *what, GLenum target)
{
    int i, k;
    printf("%s\n", what);
    for (i = 0; i < 15; i++) {
        GLenum pname = i < 14 ? tex_pnames[i] : GL_TEXTURE_COMPARE_FUNC;
        GLfloat f[4] = { -7, -7, -7, -7 };
        GLint v[4] = { -7, -7, -7, -7 };
        int n = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
        glGetTexParameterfv(target, pname, f);
        glGetTexParameteriv(target, pname, v);
        printf(" param %d", i);
        ffl_pfv("f", f, n);
        printf(" i");
        for (k = 0; k < n; k++)
            printf(" %d", (int)v[k]);
        printf("\n");
    }
}

static void print_env(const char *what)
{
    int i, k;
    GLfloat f[4] = { -7, -7, -7, -7 };
    GLint v[4] = { -7, -7, -7, -7 };
    printf("%s\n", what);
    for (i = 0; i < 18; i++) {
        GLenum pname = i < 17 ? env_pnames[i] : GL_ALPHA_SCALE;
        int n = pname == GL_TEXTURE_ENV_COLOR ? 4 : 1;
        glGetTexEnvfv(GL_TEXTURE_ENV, pname, f);
        glGetTexEnviv(GL_TEXTURE_ENV, pname, v);
        printf(" env %d", i);
        ffl_pfv("f", f, n);
        printf(" i");
        for (k = 0; k < n; k++)
            printf(" %d", (int)v[k]);
        printf("\n");
    }
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, f);
    ffl_pfv(" lod_bias f", f, 1);
    printf("\n");
}

static void print_bindings(const char *what)
{
    printf("%s\n", what);
    ffl_print_ints(" active", GL_ACTIVE_TEXTURE, 1);
    ffl_print_ints(" binding_1d", GL_TEXTURE_BINDING_1D, 1);
    ffl_print_ints(" binding_2d", GL_TEXTURE_BINDING_2D, 1);
    ffl_print_ints(" binding_3d", GL_TEXTURE_BINDING_3D, 1);
    ffl_print_ints(" binding_cube", GL_TEXTURE_BINDING_CUBE_MAP, 1);
    ffl_print_bools(" tex1d", GL_TEXTURE_1D, 1, 1);
    ffl_print_bools(" tex2d", GL_TEXTURE_2D, 1, 1);
    ffl_print_bools(" tex3d", GL_TEXTURE_3D, 1, 1);
    ffl_print_bools(" texcube", GL_TEXTURE_CUBE_MAP, 1, 1);
}

int main(void)
{
    static const GLfloat border[4] = { 2.0f, -1.0f, 0.5f, 0.25f };
    static const GLint border_i[4] = { 2147483647, -5, 1073741823, 0 };
    static const GLfloat env_color[4] = { 0.25f, 1.5f, -0.5f, 0.75f };
    static const GLint env_color_i[4] = { 0, 2147483647, 1073741823, -100 };
    GLuint names[4], deleted[2];
    GLuint lookup[3];
    GLboolean residences[3] = { 7, 7, 7 };
    GLfloat priorities[3] = { -1.0f, 0.25f, 3.0f };
    GLfloat f;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    print_params("initial 2d", GL_TEXTURE_2D);
    print_params("initial cube", GL_TEXTURE_CUBE_MAP);
    print_env("initial env");
    print_bindings("initial");

    glGenTextures(4, names);
    printf("gen %u %u %u %u is %d\n", names[0], names[1], names[2], names[3],
           (int)glIsTexture(names[0]));
    glBindTexture(GL_TEXTURE_2D, names[0]);
    glBindTexture(GL_TEXTURE_3D, names[1]);
    printf("is %d %d %d\n", (int)glIsTexture(names[0]), (int)glIsTexture(names[1]),
           (int)glIsTexture(0));
    ffl_print_error("bind");
    glBindTexture(GL_TEXTURE_1D, names[0]);
    ffl_print_error("bind other target");
    glBindTexture(0x1234, names[2]);
    ffl_print_error("bind bad target");
    glBindTexture(GL_TEXTURE_CUBE_MAP, 100);
    printf("bind unused 100: is %d\n", (int)glIsTexture(100));
    glGenTextures(1, names + 3);
    printf("gen after 100: %u\n", names[3]);
    glGenTextures(-1, names);
    ffl_print_error("gen negative");
    print_bindings("bound on unit 0");

    /* Parameters: every pname through fv, iv, f, i; then bad values. */
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLfloat)GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.6f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 7.25f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2.7f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 9);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 5);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    ffl_print_error("params set");
    print_params("params set", GL_TEXTURE_2D);
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border_i);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
    print_params("params iv", GL_TEXTURE_2D);

    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
    ffl_print_error("min filter bad");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    ffl_print_error("mag filter bad");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_NEAREST);
    ffl_print_error("wrap bad");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
    ffl_print_error("base level negative");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -3.0f);
    ffl_print_error("max level negative");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.0f);
    ffl_print_error("border scalar");
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGB);
    ffl_print_error("depth mode bad");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LEQUAL);
    ffl_print_error("compare mode bad");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ADD);
    ffl_print_error("compare func bad");
    glTexParameteri(GL_TEXTURE_2D, 0x1234, GL_NEAREST);
    ffl_print_error("pname bad");
    glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    ffl_print_error("proxy target");
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, (GLint *)names);
    ffl_print_error("get pname bad");
    glBegin(GL_POINTS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glEnd();
    ffl_print_error("param in begin");
    print_params("after errors", GL_TEXTURE_2D);

    /* Environment. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
    glTexEnvf(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLfloat)GL_SUBTRACT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE3);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_TEXTURE7);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_ONE_MINUS_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -2.5f);
    ffl_print_error("env set");
    print_env("env set");
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color_i);
    print_env("env color iv");
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);
    ffl_print_error("rgb scale 3");
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_SUBTRACT);
    ffl_print_error("mode bad");
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
    ffl_print_error("combine alpha dot3");
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
    ffl_print_error("operand alpha color");
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE0 + 8);
    ffl_print_error("source bad");
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1.0f);
    ffl_print_error("lod bias on env");
    glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_ADD);
    ffl_print_error("env target bad");
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, &f);
    ffl_print_error("get env pname bad");
    print_env("env after errors");

    /* Units: state per unit. */
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glActiveTexture(GL_TEXTURE2);
    print_bindings("unit 2");
    print_env("unit 2 env");
    glEnable(GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    print_bindings("unit 2 set");
    print_params("unit 2 sees object's params", GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0 - 1);
    ffl_print_error("active bad");
    glActiveTexture(GL_TEXTURE0);
    print_bindings("unit 0 again");

    /* Residency, priorities, deletion. */
    lookup[0] = names[0];
    lookup[1] = names[1];
    lookup[2] = 100;
    printf("resident %d", (int)glAreTexturesResident(3, lookup, residences));
    printf(" %s %d %d %d\n", ffl_error_name(glGetError()), residences[0], residences[1],
           residences[2]);
    lookup[2] = 0;
    printf("resident zero %d", (int)glAreTexturesResident(3, lookup, residences));
    printf(" %s %d\n", ffl_error_name(glGetError()), residences[0]);
    glPrioritizeTextures(3, lookup, priorities);
    ffl_print_error("prioritize");
    glBindTexture(GL_TEXTURE_3D, names[1]);
    print_params("prioritized 3d", GL_TEXTURE_3D);
    glPrioritizeTextures(-1, lookup, priorities);
    ffl_print_error("prioritize negative");
    deleted[0] = names[0];
    deleted[1] = 100;
    glDeleteTextures(2, deleted);
    ffl_print_error("delete");
    printf("after delete is %d %d\n", (int)glIsTexture(names[0]), (int)glIsTexture(100));
    print_bindings("unit 0 after delete");
    glActiveTexture(GL_TEXTURE2);
    print_bindings("unit 2 after delete");
    print_params("default 2d", GL_TEXTURE_2D);
    glDeleteTextures(-1, deleted);
    ffl_print_error("delete negative");
    glBegin(GL_POINTS);
    printf("is in begin %d\n", (int)glIsTexture(names[1]));
    glEnd();
    ffl_print_error("is in begin");
    return 0;
}
