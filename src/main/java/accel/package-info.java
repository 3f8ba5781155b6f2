/**
 * How the renderer finds what a ray meets without testing every body: the bounding volume hierarchy
 * over a scene's bodies and the shadow bundles that trace a soft shadow's rays together.
 * <p>
 * {@link accel.BoundingVolumeHierarchy} is built once per scene from its {@link geometries.Geometries}
 * and answers two single-ray queries: the closest hit (the shading ray's) and the transmittance (a
 * shadow ray's, which stops at its first opaque blocker). A soft shadow's rays share a pyramid from the
 * shaded point to the light's square, a {@link accel.ShadowFrustum}: the hierarchy gathers the few
 * bodies that may meet it, then traces the rays against those alone, or walks a subtree with the rays
 * as one packet; a closed opaque mesh one of whose {@link accel.InnerBoxes} lies across the whole
 * pyramid blocks the bundle without a ray traced. {@code docs/acceleration.md} explains the design.
 */
package accel;
