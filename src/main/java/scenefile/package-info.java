/**
 * Scene files: XML files that describe a {@link scenefile.Picture} (a scene, its camera, the image's size
 * and how it is rendered), checked against the schema {@code scenefile/scene.xsd} shipped in the jar.
 * {@link scenefile.SceneLoader} reads one, with every error named by file, line and column
 * ({@link scenefile.SceneFileException}); {@link scenefile.SceneWriter} writes one;
 * {@link scenefile.ObjMesh} imports the triangle meshes of OBJ files that a scene file names.
 */
package scenefile;
