/**
 * The lights of a scene: the {@link lighting.AmbientLight} every body receives, and the light sources a
 * body is lit and shadowed by: {@link lighting.DirectionalLight}, {@link lighting.PointLight} (attenuated
 * by distance) and {@link lighting.SpotLight} (a point light aimed in a direction).
 * <p>
 * Point and spot lights are {@link lighting.AreaLightSource}s: squares of edge
 * {@link lighting.PointLight#setEdgesSize(double)}, placed by {@link lighting.PointLight#setUV}, that cast soft
 * shadows when the renderer's soft shadows are on.
 */
package lighting;
