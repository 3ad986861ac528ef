#ifndef TL_NOISE_H
#define TL_NOISE_H

/* The value noise of shaders/foam_noise.glsl's foam_noise in double, in [0, 1]:
 * the same integer hash at the same cells, so the CPU mirrors of what the
 * shaders shape with it (the giant wave's spray and lip, the bow's spray)
 * match the GPU's to rounding. */
double tl_noise_value(double x, double y);

/* Where foam_cells puts a cell's point: TL_NOISE_CELL_MARGIN of the cell
 * in from each side (points nearer the borders than that drew slivers of
 * cells), its second coordinate hashed at the cell shifted by
 * (TL_NOISE_CELL_SHIFT_X, _Y). */
#define TL_NOISE_CELL_MARGIN  0.1
#define TL_NOISE_CELL_SHIFT_X 113
#define TL_NOISE_CELL_SHIFT_Y 71

/* shaders/foam_noise.glsl's foam_cells in double: the distance from (x, y)
 * to the border between the cells of its two nearest points (one point
 * per unit cell), F2 - F1 of a cellular noise; 0 on a border. */
double tl_noise_cells(double x, double y);

#endif
