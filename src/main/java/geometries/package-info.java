/**
 * The bodies a ray can hit, and how the renderer finds the one it hits first.
 * <p>
 * {@link geometries.Intersectable} is anything a ray can hit; its queries return null when the ray misses,
 * as the course's tests expect. {@link geometries.Geometry} is a single body with an emission and a
 * material: {@link geometries.Sphere}, {@link geometries.Plane}, {@link geometries.Polygon},
 * {@link geometries.Triangle}, {@link geometries.Tube} and {@link geometries.Cylinder}.
 * {@link geometries.Geometries} is the composite that holds a scene's bodies.
 * <p>
 * Polygon edges follow two rules: the course's queries on a body take it as open (a ray through an edge
 * misses), the renderer's path takes it as closed, so meshes render without seams (see
 * {@link geometries.Polygon}). The renderer's path is the {@link geometries.BoundingVolumeHierarchy}, which
 * also traces the shadow rays of a soft shadow as one bundle inside a {@link geometries.ShadowFrustum}.
 */
package geometries;
