/**
 * The programs: the main class ({@link app.Main}), which renders the example gallery ({@link app.Gallery}) or
 * runs the command line ({@link app.RenderCommand}) on a scene file; the scene files themselves — read by
 * {@link app.SceneLoader}, written by {@link app.SceneWriter}, checked against the schema
 * {@code app/scene.xsd}, with triangle meshes imported from OBJ files by {@link app.ObjMesh}.
 */
package app;
