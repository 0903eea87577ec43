/* How many values each pname of a query returns, for tests/sweep/sweep.c: taken from the
 * OpenGL 1.5 specification's state tables (§6.2, tables 6.5 to 6.32: the "Type" column,
 * "4 × Z" is 4 values, "C" a color of 4, "P" a position of 4, "D" a direction of 3, "N" a
 * normal of 3, "T" texture coordinates of 4, "M4" a matrix of 16, "Rk" k values, "n × T"
 * n copies of which a query returns the one selected) and §6.1 (glGetQuery*, glGetPointerv,
 * glGetBufferPointerv: one value each), never from fflight's source. §6.2: state listed
 * with glIsEnabled can be obtained with glGetBooleanv/Integerv/Floatv/Doublev too (one
 * value); so can anything listed with one of those four. OpenGL ES 1.1 adds glGetFixedv
 * (the same pnames) and the x forms of the light, material, texture environment and texture
 * parameter queries, with no pname this header lacks.
 *
 * A pname a query accepts (no error) that is not in its table fails the sweep, so the table
 * stays complete; a query writing another number of values than its table gives fails it. */
#ifndef SWEEP_PNAME_COUNTS_H
#define SWEEP_PNAME_COUNTS_H

/* GL 1.5 state include/fflight.h has no name for (values of <GL/gl.h>). */
#ifndef GL_CURRENT_RASTER_INDEX
#define GL_CURRENT_RASTER_INDEX 0x0B05
#endif
#ifndef GL_POINT_SIZE_GRANULARITY
#define GL_POINT_SIZE_GRANULARITY 0x0B13
#endif
#ifndef GL_LINE_WIDTH_GRANULARITY
#define GL_LINE_WIDTH_GRANULARITY 0x0B23
#endif
#ifndef GL_INDEX_MODE
#define GL_INDEX_MODE 0x0C30
#endif
#ifndef GL_RGBA_MODE
#define GL_RGBA_MODE 0x0C31
#endif
#ifndef GL_SUBPIXEL_BITS
#define GL_SUBPIXEL_BITS 0x0D50
#endif
#ifndef GL_INDEX_BITS
#define GL_INDEX_BITS 0x0D51
#endif
#ifndef GL_RED_BITS
#define GL_RED_BITS 0x0D52
#endif
#ifndef GL_GREEN_BITS
#define GL_GREEN_BITS 0x0D53
#endif
#ifndef GL_BLUE_BITS
#define GL_BLUE_BITS 0x0D54
#endif
#ifndef GL_ALPHA_BITS
#define GL_ALPHA_BITS 0x0D55
#endif
#ifndef GL_DEPTH_BITS
#define GL_DEPTH_BITS 0x0D56
#endif
#ifndef GL_ALIASED_POINT_SIZE_RANGE
#define GL_ALIASED_POINT_SIZE_RANGE 0x846D
#endif
#ifndef GL_ALIASED_LINE_WIDTH_RANGE
#define GL_ALIASED_LINE_WIDTH_RANGE 0x846E
#endif

struct pname_count {
    GLenum pname;
    int count; /* PNAME_COMPRESSED_FORMATS: GL_NUM_COMPRESSED_TEXTURE_FORMATS values */
};
#define PNAME_COMPRESSED_FORMATS (-1)

/* glGetBooleanv, glGetIntegerv, glGetFloatv, glGetDoublev, glGetFixedv. */
static const struct pname_count GET_COUNTS[] = {
    /* Table 6.5, current values */
    { GL_CURRENT_COLOR, 4 }, { GL_CURRENT_SECONDARY_COLOR, 4 }, { GL_CURRENT_INDEX, 1 },
    { GL_CURRENT_TEXTURE_COORDS, 4 }, { GL_CURRENT_NORMAL, 3 }, { GL_CURRENT_FOG_COORD, 1 },
    { GL_CURRENT_RASTER_POSITION, 4 }, { GL_CURRENT_RASTER_DISTANCE, 1 },
    { GL_CURRENT_RASTER_COLOR, 4 }, { GL_CURRENT_RASTER_INDEX, 1 },
    { GL_CURRENT_RASTER_TEXTURE_COORDS, 4 }, { GL_CURRENT_RASTER_POSITION_VALID, 1 },
    { GL_EDGE_FLAG, 1 },
    /* not in 1.5's tables: OpenGL 2.1's table 6.5 lists it, type C */
    { GL_CURRENT_RASTER_SECONDARY_COLOR, 4 },
    /* Tables 6.6 and 6.7, vertex arrays (the pointers: glGetPointerv only) */
    { GL_CLIENT_ACTIVE_TEXTURE, 1 }, { GL_VERTEX_ARRAY, 1 }, { GL_VERTEX_ARRAY_SIZE, 1 },
    { GL_VERTEX_ARRAY_TYPE, 1 }, { GL_VERTEX_ARRAY_STRIDE, 1 }, { GL_NORMAL_ARRAY, 1 },
    { GL_NORMAL_ARRAY_TYPE, 1 }, { GL_NORMAL_ARRAY_STRIDE, 1 }, { GL_FOG_COORD_ARRAY, 1 },
    { GL_FOG_COORD_ARRAY_TYPE, 1 }, { GL_FOG_COORD_ARRAY_STRIDE, 1 }, { GL_COLOR_ARRAY, 1 },
    { GL_COLOR_ARRAY_SIZE, 1 }, { GL_COLOR_ARRAY_TYPE, 1 }, { GL_COLOR_ARRAY_STRIDE, 1 },
    { GL_SECONDARY_COLOR_ARRAY, 1 }, { GL_SECONDARY_COLOR_ARRAY_SIZE, 1 },
    { GL_SECONDARY_COLOR_ARRAY_TYPE, 1 }, { GL_SECONDARY_COLOR_ARRAY_STRIDE, 1 },
    { GL_INDEX_ARRAY, 1 }, { GL_INDEX_ARRAY_TYPE, 1 }, { GL_INDEX_ARRAY_STRIDE, 1 },
    { GL_TEXTURE_COORD_ARRAY, 1 }, { GL_TEXTURE_COORD_ARRAY_SIZE, 1 },
    { GL_TEXTURE_COORD_ARRAY_TYPE, 1 }, { GL_TEXTURE_COORD_ARRAY_STRIDE, 1 },
    { GL_EDGE_FLAG_ARRAY, 1 }, { GL_EDGE_FLAG_ARRAY_STRIDE, 1 }, { GL_ARRAY_BUFFER_BINDING, 1 },
    { GL_VERTEX_ARRAY_BUFFER_BINDING, 1 }, { GL_NORMAL_ARRAY_BUFFER_BINDING, 1 },
    { GL_COLOR_ARRAY_BUFFER_BINDING, 1 }, { GL_INDEX_ARRAY_BUFFER_BINDING, 1 },
    { GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1 }, { GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1 },
    { GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 1 }, { GL_FOG_COORD_ARRAY_BUFFER_BINDING, 1 },
    { GL_ELEMENT_ARRAY_BUFFER_BINDING, 1 },
    /* Table 6.9, transformation */
    { GL_COLOR_MATRIX, 16 }, { GL_TRANSPOSE_COLOR_MATRIX, 16 }, { GL_MODELVIEW_MATRIX, 16 },
    { GL_TRANSPOSE_MODELVIEW_MATRIX, 16 }, { GL_PROJECTION_MATRIX, 16 },
    { GL_TRANSPOSE_PROJECTION_MATRIX, 16 }, { GL_TEXTURE_MATRIX, 16 },
    { GL_TRANSPOSE_TEXTURE_MATRIX, 16 }, { GL_VIEWPORT, 4 }, { GL_DEPTH_RANGE, 2 },
    { GL_COLOR_MATRIX_STACK_DEPTH, 1 }, { GL_MODELVIEW_STACK_DEPTH, 1 },
    { GL_PROJECTION_STACK_DEPTH, 1 }, { GL_TEXTURE_STACK_DEPTH, 1 }, { GL_MATRIX_MODE, 1 },
    { GL_NORMALIZE, 1 }, { GL_RESCALE_NORMAL, 1 }, { GL_CLIP_PLANE0, 1 }, { GL_CLIP_PLANE1, 1 },
    { GL_CLIP_PLANE2, 1 }, { GL_CLIP_PLANE3, 1 }, { GL_CLIP_PLANE4, 1 }, { GL_CLIP_PLANE5, 1 },
    /* Table 6.10, coloring */
    { GL_FOG_COLOR, 4 }, { GL_FOG_INDEX, 1 }, { GL_FOG_DENSITY, 1 }, { GL_FOG_START, 1 },
    { GL_FOG_END, 1 }, { GL_FOG_MODE, 1 }, { GL_FOG, 1 }, { GL_FOG_COORD_SRC, 1 },
    { GL_COLOR_SUM, 1 }, { GL_SHADE_MODEL, 1 },
    /* Tables 6.11 and 6.12, lighting */
    { GL_LIGHTING, 1 }, { GL_COLOR_MATERIAL, 1 }, { GL_COLOR_MATERIAL_PARAMETER, 1 },
    { GL_COLOR_MATERIAL_FACE, 1 }, { GL_LIGHT_MODEL_AMBIENT, 4 },
    { GL_LIGHT_MODEL_LOCAL_VIEWER, 1 }, { GL_LIGHT_MODEL_TWO_SIDE, 1 },
    { GL_LIGHT_MODEL_COLOR_CONTROL, 1 }, { GL_LIGHT0, 1 }, { GL_LIGHT1, 1 }, { GL_LIGHT2, 1 },
    { GL_LIGHT3, 1 }, { GL_LIGHT4, 1 }, { GL_LIGHT5, 1 }, { GL_LIGHT6, 1 }, { GL_LIGHT7, 1 },
    /* Table 6.13, rasterization */
    { GL_POINT_SIZE, 1 }, { GL_POINT_SMOOTH, 1 }, { GL_POINT_SIZE_MIN, 1 },
    { GL_POINT_SIZE_MAX, 1 }, { GL_POINT_FADE_THRESHOLD_SIZE, 1 },
    { GL_POINT_DISTANCE_ATTENUATION, 3 }, { GL_LINE_WIDTH, 1 }, { GL_LINE_SMOOTH, 1 },
    { GL_LINE_STIPPLE_PATTERN, 1 }, { GL_LINE_STIPPLE_REPEAT, 1 }, { GL_LINE_STIPPLE, 1 },
    { GL_CULL_FACE, 1 }, { GL_CULL_FACE_MODE, 1 }, { GL_FRONT_FACE, 1 }, { GL_POLYGON_SMOOTH, 1 },
    { GL_POLYGON_MODE, 2 }, { GL_POLYGON_OFFSET_FACTOR, 1 }, { GL_POLYGON_OFFSET_UNITS, 1 },
    { GL_POLYGON_OFFSET_POINT, 1 }, { GL_POLYGON_OFFSET_LINE, 1 }, { GL_POLYGON_OFFSET_FILL, 1 },
    { GL_POLYGON_STIPPLE, 1 },
    /* Table 6.14, multisampling */
    { GL_MULTISAMPLE, 1 }, { GL_SAMPLE_ALPHA_TO_COVERAGE, 1 }, { GL_SAMPLE_ALPHA_TO_ONE, 1 },
    { GL_SAMPLE_COVERAGE, 1 }, { GL_SAMPLE_COVERAGE_VALUE, 1 }, { GL_SAMPLE_COVERAGE_INVERT, 1 },
    /* Tables 6.15 and 6.18, texture units */
    { GL_TEXTURE_1D, 1 }, { GL_TEXTURE_2D, 1 }, { GL_TEXTURE_3D, 1 }, { GL_TEXTURE_CUBE_MAP, 1 },
    { GL_TEXTURE_BINDING_1D, 1 }, { GL_TEXTURE_BINDING_2D, 1 }, { GL_TEXTURE_BINDING_3D, 1 },
    { GL_TEXTURE_BINDING_CUBE_MAP, 1 }, { GL_ACTIVE_TEXTURE, 1 }, { GL_TEXTURE_GEN_S, 1 },
    { GL_TEXTURE_GEN_T, 1 }, { GL_TEXTURE_GEN_R, 1 }, { GL_TEXTURE_GEN_Q, 1 },
    /* Table 6.19, pixel operations (v1.3 names: BLEND_SRC, BLEND_DST, LOGIC_OP) */
    { GL_SCISSOR_TEST, 1 }, { GL_SCISSOR_BOX, 4 }, { GL_ALPHA_TEST, 1 }, { GL_ALPHA_TEST_FUNC, 1 },
    { GL_ALPHA_TEST_REF, 1 }, { GL_STENCIL_TEST, 1 }, { GL_STENCIL_FUNC, 1 },
    { GL_STENCIL_VALUE_MASK, 1 }, { GL_STENCIL_REF, 1 }, { GL_STENCIL_FAIL, 1 },
    { GL_STENCIL_PASS_DEPTH_FAIL, 1 }, { GL_STENCIL_PASS_DEPTH_PASS, 1 }, { GL_DEPTH_TEST, 1 },
    { GL_DEPTH_FUNC, 1 }, { GL_BLEND, 1 }, { GL_BLEND_SRC_RGB, 1 }, { GL_BLEND_SRC, 1 },
    { GL_BLEND_SRC_ALPHA, 1 }, { GL_BLEND_DST_RGB, 1 }, { GL_BLEND_DST, 1 },
    { GL_BLEND_DST_ALPHA, 1 }, { GL_BLEND_EQUATION, 1 }, { GL_BLEND_COLOR, 4 }, { GL_DITHER, 1 },
    { GL_INDEX_LOGIC_OP, 1 }, { GL_COLOR_LOGIC_OP, 1 }, { GL_LOGIC_OP_MODE, 1 },
    /* Table 6.20, framebuffer control */
    { GL_DRAW_BUFFER, 1 }, { GL_INDEX_WRITEMASK, 1 }, { GL_COLOR_WRITEMASK, 4 },
    { GL_DEPTH_WRITEMASK, 1 }, { GL_STENCIL_WRITEMASK, 1 }, { GL_COLOR_CLEAR_VALUE, 4 },
    { GL_INDEX_CLEAR_VALUE, 1 }, { GL_DEPTH_CLEAR_VALUE, 1 }, { GL_STENCIL_CLEAR_VALUE, 1 },
    { GL_ACCUM_CLEAR_VALUE, 4 },
    /* Tables 6.21 to 6.25, pixels */
    { GL_UNPACK_SWAP_BYTES, 1 }, { GL_UNPACK_LSB_FIRST, 1 }, { GL_UNPACK_IMAGE_HEIGHT, 1 },
    { GL_UNPACK_SKIP_IMAGES, 1 }, { GL_UNPACK_ROW_LENGTH, 1 }, { GL_UNPACK_SKIP_ROWS, 1 },
    { GL_UNPACK_SKIP_PIXELS, 1 }, { GL_UNPACK_ALIGNMENT, 1 }, { GL_PACK_SWAP_BYTES, 1 },
    { GL_PACK_LSB_FIRST, 1 }, { GL_PACK_IMAGE_HEIGHT, 1 }, { GL_PACK_SKIP_IMAGES, 1 },
    { GL_PACK_ROW_LENGTH, 1 }, { GL_PACK_SKIP_ROWS, 1 }, { GL_PACK_SKIP_PIXELS, 1 },
    { GL_PACK_ALIGNMENT, 1 }, { GL_MAP_COLOR, 1 }, { GL_MAP_STENCIL, 1 }, { GL_INDEX_SHIFT, 1 },
    { GL_INDEX_OFFSET, 1 }, { GL_RED_SCALE, 1 }, { GL_GREEN_SCALE, 1 }, { GL_BLUE_SCALE, 1 },
    { GL_ALPHA_SCALE, 1 }, { GL_DEPTH_SCALE, 1 }, { GL_RED_BIAS, 1 }, { GL_GREEN_BIAS, 1 },
    { GL_BLUE_BIAS, 1 }, { GL_ALPHA_BIAS, 1 }, { GL_DEPTH_BIAS, 1 }, { GL_COLOR_TABLE, 1 },
    { GL_POST_CONVOLUTION_COLOR_TABLE, 1 }, { GL_POST_COLOR_MATRIX_COLOR_TABLE, 1 },
    { GL_CONVOLUTION_1D, 1 }, { GL_CONVOLUTION_2D, 1 }, { GL_SEPARABLE_2D, 1 },
    { GL_POST_CONVOLUTION_RED_SCALE, 1 }, { GL_POST_CONVOLUTION_GREEN_SCALE, 1 },
    { GL_POST_CONVOLUTION_BLUE_SCALE, 1 }, { GL_POST_CONVOLUTION_ALPHA_SCALE, 1 },
    { GL_POST_CONVOLUTION_RED_BIAS, 1 }, { GL_POST_CONVOLUTION_GREEN_BIAS, 1 },
    { GL_POST_CONVOLUTION_BLUE_BIAS, 1 }, { GL_POST_CONVOLUTION_ALPHA_BIAS, 1 },
    { GL_POST_COLOR_MATRIX_RED_SCALE, 1 }, { GL_POST_COLOR_MATRIX_GREEN_SCALE, 1 },
    { GL_POST_COLOR_MATRIX_BLUE_SCALE, 1 }, { GL_POST_COLOR_MATRIX_ALPHA_SCALE, 1 },
    { GL_POST_COLOR_MATRIX_RED_BIAS, 1 }, { GL_POST_COLOR_MATRIX_GREEN_BIAS, 1 },
    { GL_POST_COLOR_MATRIX_BLUE_BIAS, 1 }, { GL_POST_COLOR_MATRIX_ALPHA_BIAS, 1 },
    { GL_HISTOGRAM, 1 }, { GL_MINMAX, 1 }, { GL_ZOOM_X, 1 }, { GL_ZOOM_Y, 1 },
    { GL_PIXEL_MAP_I_TO_I_SIZE, 1 }, { GL_PIXEL_MAP_S_TO_S_SIZE, 1 },
    { GL_PIXEL_MAP_I_TO_R_SIZE, 1 }, { GL_PIXEL_MAP_I_TO_G_SIZE, 1 },
    { GL_PIXEL_MAP_I_TO_B_SIZE, 1 }, { GL_PIXEL_MAP_I_TO_A_SIZE, 1 },
    { GL_PIXEL_MAP_R_TO_R_SIZE, 1 }, { GL_PIXEL_MAP_G_TO_G_SIZE, 1 },
    { GL_PIXEL_MAP_B_TO_B_SIZE, 1 }, { GL_PIXEL_MAP_A_TO_A_SIZE, 1 }, { GL_READ_BUFFER, 1 },
    /* Table 6.26, evaluators */
    { GL_MAP1_COLOR_4, 1 }, { GL_MAP1_INDEX, 1 }, { GL_MAP1_NORMAL, 1 },
    { GL_MAP1_TEXTURE_COORD_1, 1 }, { GL_MAP1_TEXTURE_COORD_2, 1 },
    { GL_MAP1_TEXTURE_COORD_3, 1 }, { GL_MAP1_TEXTURE_COORD_4, 1 }, { GL_MAP1_VERTEX_3, 1 },
    { GL_MAP1_VERTEX_4, 1 }, { GL_MAP2_COLOR_4, 1 }, { GL_MAP2_INDEX, 1 }, { GL_MAP2_NORMAL, 1 },
    { GL_MAP2_TEXTURE_COORD_1, 1 }, { GL_MAP2_TEXTURE_COORD_2, 1 },
    { GL_MAP2_TEXTURE_COORD_3, 1 }, { GL_MAP2_TEXTURE_COORD_4, 1 }, { GL_MAP2_VERTEX_3, 1 },
    { GL_MAP2_VERTEX_4, 1 }, { GL_MAP1_GRID_DOMAIN, 2 }, { GL_MAP2_GRID_DOMAIN, 4 },
    { GL_MAP1_GRID_SEGMENTS, 1 }, { GL_MAP2_GRID_SEGMENTS, 2 }, { GL_AUTO_NORMAL, 1 },
    /* Table 6.27, hints */
    { GL_PERSPECTIVE_CORRECTION_HINT, 1 }, { GL_POINT_SMOOTH_HINT, 1 },
    { GL_LINE_SMOOTH_HINT, 1 }, { GL_POLYGON_SMOOTH_HINT, 1 }, { GL_FOG_HINT, 1 },
    { GL_GENERATE_MIPMAP_HINT, 1 }, { GL_TEXTURE_COMPRESSION_HINT, 1 },
    /* Tables 6.28 to 6.31, implementation-dependent values (v1.1 names: POINT_SIZE_RANGE,
     * POINT_SIZE_GRANULARITY, LINE_WIDTH_RANGE, LINE_WIDTH_GRANULARITY) */
    { GL_MAX_LIGHTS, 1 }, { GL_MAX_CLIP_PLANES, 1 }, { GL_MAX_COLOR_MATRIX_STACK_DEPTH, 1 },
    { GL_MAX_MODELVIEW_STACK_DEPTH, 1 }, { GL_MAX_PROJECTION_STACK_DEPTH, 1 },
    { GL_MAX_TEXTURE_STACK_DEPTH, 1 }, { GL_SUBPIXEL_BITS, 1 }, { GL_MAX_3D_TEXTURE_SIZE, 1 },
    { GL_MAX_TEXTURE_SIZE, 1 }, { GL_MAX_TEXTURE_LOD_BIAS, 1 },
    { GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1 }, { GL_MAX_PIXEL_MAP_TABLE, 1 },
    { GL_MAX_NAME_STACK_DEPTH, 1 }, { GL_MAX_LIST_NESTING, 1 }, { GL_MAX_EVAL_ORDER, 1 },
    { GL_MAX_VIEWPORT_DIMS, 2 }, { GL_MAX_ATTRIB_STACK_DEPTH, 1 },
    { GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1 }, { GL_AUX_BUFFERS, 1 }, { GL_RGBA_MODE, 1 },
    { GL_INDEX_MODE, 1 }, { GL_DOUBLEBUFFER, 1 }, { GL_STEREO, 1 },
    { GL_ALIASED_POINT_SIZE_RANGE, 2 }, { GL_POINT_SIZE_RANGE, 2 },
    { GL_POINT_SIZE_GRANULARITY, 1 }, { GL_ALIASED_LINE_WIDTH_RANGE, 2 },
    { GL_LINE_WIDTH_RANGE, 2 }, { GL_LINE_WIDTH_GRANULARITY, 1 },
    { GL_MAX_ELEMENTS_INDICES, 1 }, { GL_MAX_ELEMENTS_VERTICES, 1 }, { GL_MAX_TEXTURE_UNITS, 1 },
    { GL_SAMPLE_BUFFERS, 1 }, { GL_SAMPLES, 1 },
    { GL_COMPRESSED_TEXTURE_FORMATS, PNAME_COMPRESSED_FORMATS },
    { GL_NUM_COMPRESSED_TEXTURE_FORMATS, 1 }, { GL_RED_BITS, 1 }, { GL_GREEN_BITS, 1 },
    { GL_BLUE_BITS, 1 }, { GL_ALPHA_BITS, 1 }, { GL_INDEX_BITS, 1 }, { GL_DEPTH_BITS, 1 },
    { GL_STENCIL_BITS, 1 }, { GL_ACCUM_RED_BITS, 1 }, { GL_ACCUM_GREEN_BITS, 1 },
    { GL_ACCUM_BLUE_BITS, 1 }, { GL_ACCUM_ALPHA_BITS, 1 },
    /* Table 6.32, miscellaneous */
    { GL_LIST_BASE, 1 }, { GL_LIST_INDEX, 1 }, { GL_LIST_MODE, 1 }, { GL_ATTRIB_STACK_DEPTH, 1 },
    { GL_CLIENT_ATTRIB_STACK_DEPTH, 1 }, { GL_NAME_STACK_DEPTH, 1 }, { GL_RENDER_MODE, 1 },
    { GL_SELECTION_BUFFER_SIZE, 1 }, { GL_FEEDBACK_BUFFER_SIZE, 1 },
    { GL_FEEDBACK_BUFFER_TYPE, 1 },
};

/* Table 6.12: glGetLight*v. */
static const struct pname_count LIGHT_COUNTS[] = {
    { GL_AMBIENT, 4 }, { GL_DIFFUSE, 4 }, { GL_SPECULAR, 4 }, { GL_POSITION, 4 },
    { GL_CONSTANT_ATTENUATION, 1 }, { GL_LINEAR_ATTENUATION, 1 },
    { GL_QUADRATIC_ATTENUATION, 1 }, { GL_SPOT_DIRECTION, 3 }, { GL_SPOT_EXPONENT, 1 },
    { GL_SPOT_CUTOFF, 1 },
};

/* Tables 6.11 and 6.12: glGetMaterial*v (COLOR_INDEXES: 2 × 3 × R, one face's 3). */
static const struct pname_count MATERIAL_COUNTS[] = {
    { GL_AMBIENT, 4 }, { GL_DIFFUSE, 4 }, { GL_SPECULAR, 4 }, { GL_EMISSION, 4 },
    { GL_SHININESS, 1 }, { GL_COLOR_INDEXES, 3 },
};

/* Table 6.18: glGetTexEnv*v (target TEXTURE_ENV; TEXTURE_LOD_BIAS of TEXTURE_FILTER_CONTROL). */
static const struct pname_count TEX_ENV_COUNTS[] = {
    { GL_TEXTURE_ENV_MODE, 1 }, { GL_TEXTURE_ENV_COLOR, 4 }, { GL_TEXTURE_LOD_BIAS, 1 },
    { GL_COMBINE_RGB, 1 }, { GL_COMBINE_ALPHA, 1 }, { GL_SOURCE0_RGB, 1 }, { GL_SOURCE1_RGB, 1 },
    { GL_SOURCE2_RGB, 1 }, { GL_SOURCE0_ALPHA, 1 }, { GL_SOURCE1_ALPHA, 1 },
    { GL_SOURCE2_ALPHA, 1 }, { GL_OPERAND0_RGB, 1 }, { GL_OPERAND1_RGB, 1 },
    { GL_OPERAND2_RGB, 1 }, { GL_OPERAND0_ALPHA, 1 }, { GL_OPERAND1_ALPHA, 1 },
    { GL_OPERAND2_ALPHA, 1 }, { GL_RGB_SCALE, 1 }, { GL_ALPHA_SCALE, 1 },
};

/* Table 6.18: glGetTexGen*v. */
static const struct pname_count TEX_GEN_COUNTS[] = {
    { GL_EYE_PLANE, 4 }, { GL_OBJECT_PLANE, 4 }, { GL_TEXTURE_GEN_MODE, 1 },
};

/* Table 6.16: glGetTexParameter*v. */
static const struct pname_count TEX_PARAMETER_COUNTS[] = {
    { GL_TEXTURE_BORDER_COLOR, 4 }, { GL_TEXTURE_MIN_FILTER, 1 }, { GL_TEXTURE_MAG_FILTER, 1 },
    { GL_TEXTURE_WRAP_S, 1 }, { GL_TEXTURE_WRAP_T, 1 }, { GL_TEXTURE_WRAP_R, 1 },
    { GL_TEXTURE_PRIORITY, 1 }, { GL_TEXTURE_RESIDENT, 1 }, { GL_TEXTURE_MIN_LOD, 1 },
    { GL_TEXTURE_MAX_LOD, 1 }, { GL_TEXTURE_BASE_LEVEL, 1 }, { GL_TEXTURE_MAX_LEVEL, 1 },
    { GL_TEXTURE_LOD_BIAS, 1 }, { GL_DEPTH_TEXTURE_MODE, 1 }, { GL_TEXTURE_COMPARE_MODE, 1 },
    { GL_TEXTURE_COMPARE_FUNC, 1 }, { GL_GENERATE_MIPMAP, 1 },
};

/* Table 6.17: glGetTexLevelParameter*v (TEXTURE_COMPONENTS: INTERNAL_FORMAT's v1.0 name). */
static const struct pname_count TEX_LEVEL_PARAMETER_COUNTS[] = {
    { GL_TEXTURE_WIDTH, 1 }, { GL_TEXTURE_HEIGHT, 1 }, { GL_TEXTURE_DEPTH, 1 },
    { GL_TEXTURE_BORDER, 1 }, { GL_TEXTURE_INTERNAL_FORMAT, 1 }, { GL_TEXTURE_RED_SIZE, 1 },
    { GL_TEXTURE_GREEN_SIZE, 1 }, { GL_TEXTURE_BLUE_SIZE, 1 }, { GL_TEXTURE_ALPHA_SIZE, 1 },
    { GL_TEXTURE_LUMINANCE_SIZE, 1 }, { GL_TEXTURE_INTENSITY_SIZE, 1 },
    { GL_TEXTURE_DEPTH_SIZE, 1 }, { GL_TEXTURE_COMPRESSED, 1 },
    { GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 1 },
};

/* Tables 6.6, 6.7 and 6.32: glGetPointerv. */
static const struct pname_count POINTER_COUNTS[] = {
    { GL_VERTEX_ARRAY_POINTER, 1 }, { GL_NORMAL_ARRAY_POINTER, 1 },
    { GL_FOG_COORD_ARRAY_POINTER, 1 }, { GL_COLOR_ARRAY_POINTER, 1 },
    { GL_SECONDARY_COLOR_ARRAY_POINTER, 1 }, { GL_INDEX_ARRAY_POINTER, 1 },
    { GL_TEXTURE_COORD_ARRAY_POINTER, 1 }, { GL_EDGE_FLAG_ARRAY_POINTER, 1 },
    { GL_SELECTION_BUFFER_POINTER, 1 }, { GL_FEEDBACK_BUFFER_POINTER, 1 },
};

/* Table 6.8: glGetBufferParameteriv and glGetBufferPointerv. */
static const struct pname_count BUFFER_PARAMETER_COUNTS[] = {
    { GL_BUFFER_SIZE, 1 }, { GL_BUFFER_USAGE, 1 }, { GL_BUFFER_ACCESS, 1 },
    { GL_BUFFER_MAPPED, 1 },
};
static const struct pname_count BUFFER_POINTER_COUNTS[] = { { GL_BUFFER_MAP_POINTER, 1 } };

/* §6.1.12, tables 6.30 and 6.32: glGetQueryiv, glGetQueryObject[u]iv. */
static const struct pname_count QUERY_COUNTS[] = {
    { GL_CURRENT_QUERY, 1 }, { GL_QUERY_COUNTER_BITS, 1 },
};
static const struct pname_count QUERY_OBJECT_COUNTS[] = {
    { GL_QUERY_RESULT, 1 }, { GL_QUERY_RESULT_AVAILABLE, 1 },
};

/* Table 6.22: glGetColorTableParameter*v. */
static const struct pname_count COLOR_TABLE_COUNTS[] = {
    { GL_COLOR_TABLE_FORMAT, 1 }, { GL_COLOR_TABLE_WIDTH, 1 }, { GL_COLOR_TABLE_RED_SIZE, 1 },
    { GL_COLOR_TABLE_GREEN_SIZE, 1 }, { GL_COLOR_TABLE_BLUE_SIZE, 1 },
    { GL_COLOR_TABLE_ALPHA_SIZE, 1 }, { GL_COLOR_TABLE_LUMINANCE_SIZE, 1 },
    { GL_COLOR_TABLE_INTENSITY_SIZE, 1 }, { GL_COLOR_TABLE_SCALE, 4 },
    { GL_COLOR_TABLE_BIAS, 4 },
};

/* Tables 6.23 and 6.30: glGetConvolutionParameter*v. */
static const struct pname_count CONVOLUTION_COUNTS[] = {
    { GL_CONVOLUTION_BORDER_COLOR, 4 }, { GL_CONVOLUTION_BORDER_MODE, 1 },
    { GL_CONVOLUTION_FILTER_SCALE, 4 }, { GL_CONVOLUTION_FILTER_BIAS, 4 },
    { GL_CONVOLUTION_FORMAT, 1 }, { GL_CONVOLUTION_WIDTH, 1 }, { GL_CONVOLUTION_HEIGHT, 1 },
    { GL_MAX_CONVOLUTION_WIDTH, 1 }, { GL_MAX_CONVOLUTION_HEIGHT, 1 },
};

/* Tables 6.24 and 6.25: glGetHistogramParameter*v, glGetMinmaxParameter*v. */
static const struct pname_count HISTOGRAM_COUNTS[] = {
    { GL_HISTOGRAM_WIDTH, 1 }, { GL_HISTOGRAM_FORMAT, 1 }, { GL_HISTOGRAM_RED_SIZE, 1 },
    { GL_HISTOGRAM_GREEN_SIZE, 1 }, { GL_HISTOGRAM_BLUE_SIZE, 1 },
    { GL_HISTOGRAM_ALPHA_SIZE, 1 }, { GL_HISTOGRAM_LUMINANCE_SIZE, 1 },
    { GL_HISTOGRAM_SINK, 1 },
};
static const struct pname_count MINMAX_COUNTS[] = { { GL_MINMAX_FORMAT, 1 }, { GL_MINMAX_SINK, 1 } };

/* Which queries take which table: the function's name starts with `prefix`; `room` is the
 * most values any pname may write (the buffer beyond a pname's count, up to room, holds
 * canaries), `targets` the first arguments the exhaustive pass gives (0 ends the list; the
 * query object queries get a query object's name). */
struct pname_query {
    const char *prefix;
    const struct pname_count *table;
    size_t size;
    int room;
    GLenum targets[4];
};
#define PNAME_TABLE(t) t, sizeof t / sizeof t[0]
static const struct pname_query PNAME_QUERIES[] = {
    { "glGetBooleanv", PNAME_TABLE(GET_COUNTS), 16, { 0 } },
    { "glGetIntegerv", PNAME_TABLE(GET_COUNTS), 16, { 0 } },
    { "glGetFloatv", PNAME_TABLE(GET_COUNTS), 16, { 0 } },
    { "glGetDoublev", PNAME_TABLE(GET_COUNTS), 16, { 0 } },
    { "glGetFixedv", PNAME_TABLE(GET_COUNTS), 16, { 0 } },
    { "glGetLight", PNAME_TABLE(LIGHT_COUNTS), 4, { GL_LIGHT0, GL_LIGHT7 } },
    { "glGetMaterial", PNAME_TABLE(MATERIAL_COUNTS), 4, { GL_FRONT, GL_BACK } },
    { "glGetTexEnv", PNAME_TABLE(TEX_ENV_COUNTS), 4, { GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL } },
    { "glGetTexGen", PNAME_TABLE(TEX_GEN_COUNTS), 4, { GL_S, GL_Q } },
    { "glGetTexParameter", PNAME_TABLE(TEX_PARAMETER_COUNTS), 4,
      { GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP } },
    { "glGetTexLevelParameter", PNAME_TABLE(TEX_LEVEL_PARAMETER_COUNTS), 4,
      { GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP_POSITIVE_X } },
    { "glGetPointerv", PNAME_TABLE(POINTER_COUNTS), 4, { 0 } },
    { "glGetBufferParameter", PNAME_TABLE(BUFFER_PARAMETER_COUNTS), 4, { GL_ARRAY_BUFFER } },
    { "glGetBufferPointerv", PNAME_TABLE(BUFFER_POINTER_COUNTS), 4, { GL_ARRAY_BUFFER } },
    { "glGetQueryiv", PNAME_TABLE(QUERY_COUNTS), 4, { GL_SAMPLES_PASSED } },
    { "glGetQueryObject", PNAME_TABLE(QUERY_OBJECT_COUNTS), 4, { 0 } },
    { "glGetColorTableParameter", PNAME_TABLE(COLOR_TABLE_COUNTS), 4,
      { GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE,
        GL_PROXY_COLOR_TABLE } },
    { "glGetConvolutionParameter", PNAME_TABLE(CONVOLUTION_COUNTS), 4,
      { GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D } },
    { "glGetHistogramParameter", PNAME_TABLE(HISTOGRAM_COUNTS), 4, { GL_HISTOGRAM, GL_PROXY_HISTOGRAM } },
    { "glGetMinmaxParameter", PNAME_TABLE(MINMAX_COUNTS), 4, { GL_MINMAX } },
};

/* The commands setting the same state read as many values (§2.14.2, §3.3, §3.6.3, §3.6.5,
 * §3.8.4, §3.8.13, §3.10: each names its pnames and takes the state's type; the state tables
 * give the count): a read past the count faults against the guard page. */
static const struct pname_count MATERIAL_SET_COUNTS[] = {
    { GL_AMBIENT, 4 }, { GL_DIFFUSE, 4 }, { GL_SPECULAR, 4 }, { GL_EMISSION, 4 },
    { GL_SHININESS, 1 }, { GL_COLOR_INDEXES, 3 }, { GL_AMBIENT_AND_DIFFUSE, 4 },
};
static const struct pname_count LIGHT_MODEL_COUNTS[] = {
    { GL_LIGHT_MODEL_AMBIENT, 4 }, { GL_LIGHT_MODEL_LOCAL_VIEWER, 1 },
    { GL_LIGHT_MODEL_TWO_SIDE, 1 }, { GL_LIGHT_MODEL_COLOR_CONTROL, 1 },
};
static const struct pname_count FOG_COUNTS[] = {
    { GL_FOG_MODE, 1 }, { GL_FOG_DENSITY, 1 }, { GL_FOG_START, 1 }, { GL_FOG_END, 1 },
    { GL_FOG_INDEX, 1 }, { GL_FOG_COLOR, 4 }, { GL_FOG_COORD_SRC, 1 },
};
static const struct pname_count POINT_PARAMETER_COUNTS[] = {
    { GL_POINT_SIZE_MIN, 1 }, { GL_POINT_SIZE_MAX, 1 }, { GL_POINT_FADE_THRESHOLD_SIZE, 1 },
    { GL_POINT_DISTANCE_ATTENUATION, 3 },
};
/* Only the settable ones (§3.6.3, §3.6.5, §3.8.4: the sizes and formats are read-only, so
 * is TEXTURE_RESIDENT); a pname a command does not take gets its family's most values. */
static const struct pname_count TEX_PARAMETER_SET_COUNTS[] = {
    { GL_TEXTURE_BORDER_COLOR, 4 }, { GL_TEXTURE_MIN_FILTER, 1 }, { GL_TEXTURE_MAG_FILTER, 1 },
    { GL_TEXTURE_WRAP_S, 1 }, { GL_TEXTURE_WRAP_T, 1 }, { GL_TEXTURE_WRAP_R, 1 },
    { GL_TEXTURE_PRIORITY, 1 }, { GL_TEXTURE_MIN_LOD, 1 }, { GL_TEXTURE_MAX_LOD, 1 },
    { GL_TEXTURE_BASE_LEVEL, 1 }, { GL_TEXTURE_MAX_LEVEL, 1 }, { GL_TEXTURE_LOD_BIAS, 1 },
    { GL_DEPTH_TEXTURE_MODE, 1 }, { GL_TEXTURE_COMPARE_MODE, 1 },
    { GL_TEXTURE_COMPARE_FUNC, 1 }, { GL_GENERATE_MIPMAP, 1 },
};
static const struct pname_count COLOR_TABLE_SET_COUNTS[] = {
    { GL_COLOR_TABLE_SCALE, 4 }, { GL_COLOR_TABLE_BIAS, 4 },
};
static const struct pname_count CONVOLUTION_SET_COUNTS[] = {
    { GL_CONVOLUTION_BORDER_COLOR, 4 }, { GL_CONVOLUTION_BORDER_MODE, 1 },
    { GL_CONVOLUTION_FILTER_SCALE, 4 }, { GL_CONVOLUTION_FILTER_BIAS, 4 },
};
static const struct pname_query PNAME_SETTERS[] = {
    { "glLightModel", PNAME_TABLE(LIGHT_MODEL_COUNTS), 4, { 0 } },
    { "glLight", PNAME_TABLE(LIGHT_COUNTS), 4, { GL_LIGHT0, GL_LIGHT7 } },
    { "glMaterial", PNAME_TABLE(MATERIAL_SET_COUNTS), 4, { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK } },
    { "glFog", PNAME_TABLE(FOG_COUNTS), 4, { 0 } },
    { "glPointParameter", PNAME_TABLE(POINT_PARAMETER_COUNTS), 3, { 0 } },
    { "glTexEnv", PNAME_TABLE(TEX_ENV_COUNTS), 4, { GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL } },
    { "glTexGen", PNAME_TABLE(TEX_GEN_COUNTS), 4, { GL_S, GL_Q } },
    { "glTexParameter", PNAME_TABLE(TEX_PARAMETER_SET_COUNTS), 4,
      { GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP } },
    { "glColorTableParameter", PNAME_TABLE(COLOR_TABLE_SET_COUNTS), 4,
      { GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE } },
    { "glConvolutionParameter", PNAME_TABLE(CONVOLUTION_SET_COUNTS), 4,
      { GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_SEPARABLE_2D } },
};

#endif
