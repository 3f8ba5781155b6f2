/**
 * The basic values every other package is built from: {@link primitives.Point3D}, {@link primitives.Vector},
 * {@link primitives.Ray}, {@link primitives.Color}, {@link primitives.Material}, the textures a body's colour
 * may come from ({@link primitives.Texture}: {@link primitives.ImageTexture}, {@link primitives.CheckerTexture}),
 * the numeric helpers of {@link primitives.Util}, {@link primitives.Parallel}, which shares work among
 * threads (the render's tiles, the hierarchy's build), {@link primitives.Printable}, which makes input
 * quoted in messages safe to show on a terminal, and {@link primitives.FileNames}, which turns file names
 * into paths.
 * <p>
 * They are immutable: every operation returns a new object. The one exception is
 * {@link primitives.Vector#normalize()}, which normalises the vector itself ({@link primitives.Vector#normalized()}
 * returns a new one). Bad input (a zero vector, NaN, a negative colour) throws an
 * {@link java.lang.IllegalArgumentException} whose message names the problem.
 */
package primitives;
