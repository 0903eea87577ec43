/* ffl-test: differential */
/*
 * glColorMaterial (§2.14.3): every face (front, back, both) and mode
 * (emission, ambient, diffuse, specular, ambient and diffuse). While
 * GL_COLOR_MATERIAL is enabled the tracked material properties follow the
 * current color; points use the front material, so back tracking changes
 * nothing drawn but does change the back material, which glGetMaterialfv
 * shows. After GL_COLOR_MATERIAL is disabled the materials keep the last
 * tracked color.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

static const GLenum props[4] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION };
static const char *prop_names[4] = { "ambient", "diffuse", "specular", "emission" };

static void base_materials(ref_state *ref)
{
    mirror_material4f(ref, GL_FRONT, GL_AMBIENT, 0.2f, 0.1f, 0.1f, 1);
    mirror_material4f(ref, GL_FRONT, GL_DIFFUSE, 0.3f, 0.3f, 0.1f, 0.9f);
    mirror_material4f(ref, GL_FRONT, GL_SPECULAR, 0.2f, 0.2f, 0.2f, 1);
    mirror_material4f(ref, GL_FRONT, GL_EMISSION, 0.05f, 0.05f, 0, 1);
    mirror_material4f(ref, GL_BACK, GL_AMBIENT, 0.1f, 0.1f, 0.3f, 1);
    mirror_material4f(ref, GL_BACK, GL_DIFFUSE, 0.1f, 0.2f, 0.6f, 0.4f);
    mirror_material4f(ref, GL_BACK, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
    mirror_material4f(ref, GL_BACK, GL_EMISSION, 0, 0, 0.1f, 1);
}

/* "getmat <tag> <face> <property> val r g b a ref val r g b a" for the four
 * color properties of both faces */
static void print_materials(const ref_state *ref, const char *tag)
{
    int f, p;
    for (f = 0; f < 2; f++) {
        for (p = 0; p < 4; p++) {
            GLfloat v[4] = { -9, -9, -9, -9 };
            const ref_material *m = &ref->material[f];
            const double *expect = p == 0 ? m->ambient : p == 1 ? m->diffuse
                                 : p == 2 ? m->specular : m->emission;
            glGetMaterialfv(f == 0 ? GL_FRONT : GL_BACK, props[p], v);
            printf("getmat %s %s %s", tag, f == 0 ? "front" : "back", prop_names[p]);
            ffl_pfv("val", v, 4);
            printf(" ref");
            ffl_pdv("val", expect, 4);
            printf("\n");
        }
    }
}

int main(void)
{
    static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    static const char *face_names[3] = { "front", "back", "front_and_back" };
    static const GLenum modes[5] = { GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR,
                                     GL_AMBIENT_AND_DIFFUSE };
    static const char *mode_names[5] = { "emission", "ambient", "diffuse", "specular",
                                         "ambient_and_diffuse" };
    static const float vertices[3][3] = { { 0, 0, 0 }, { 3, 1, -2 }, { -2, -3, 4 } };
    static const float normals[3][3] = { { 0, 0, 1 }, { 0.3f, 0.2f, 0.93f }, { -0.4f, 0.1f, 0.91f } };
    static const float colors[3][4] = {
        { 0.6f, 0.3f, 0.2f, 0.8f }, { 0.1f, 0.5f, 0.4f, 0.6f }, { 0.25f, 0.35f, 0.45f, 0.3f },
    };
    ref_state ref;
    int f, m, failed = 0;
    char tag[96];

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.3f, 0.4f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_AMBIENT, 0.3f, 0.3f, 0.3f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
    mirror_materialf(&ref, GL_FRONT_AND_BACK, GL_SHININESS, 10);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (f = 0; f < 3; f++) {
        for (m = 0; m < 5; m++) {
            mirror_enable(&ref, GL_COLOR_MATERIAL, 0);
            base_materials(&ref);
            mirror_color_material(&ref, faces[f], modes[m]);
            mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
            sprintf(tag, "%s_%s", face_names[f], mode_names[m]);
            failed |= mirror_draw_points(&ref, tag, 3, vertices, normals, colors);
            print_materials(&ref, tag);
            /* disabled: the last tracked color stays in the material */
            mirror_enable(&ref, GL_COLOR_MATERIAL, 0);
            mirror_color4f(&ref, 0.9f, 0.9f, 0.1f, 1);
            sprintf(tag, "%s_%s_disabled", face_names[f], mode_names[m]);
            failed |= mirror_draw_points(&ref, tag, 1, vertices, normals, NULL);
            print_materials(&ref, tag);
        }
    }
    return failed;
}
