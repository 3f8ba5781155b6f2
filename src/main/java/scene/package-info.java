/**
 * The {@link scene.Scene}: its bodies, lights, ambient light and background, in public fields as in the
 * course, each with a setter that returns the scene.
 */
package scene;
