/**
 * The programs: the main class ({@link app.Main}), which renders the example gallery ({@link app.Gallery})
 * with no arguments, or runs the command line ({@link app.RenderCommand}) on a scene file. The scene files
 * themselves are read and written by the {@link scenefile} package.
 */
package app;
