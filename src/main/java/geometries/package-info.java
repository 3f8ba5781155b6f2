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
 * {@link geometries.Polygon}). The renderer's path goes through the hierarchy of the {@link accel} package, which
 * calls the bodies' public hooks of that path ({@code nearestHit}, {@code transmittance}, {@code bounds},
 * {@code mayMeet}): they take a ray's numbers as primitive doubles and allocate nothing.
 */
package geometries;
