// The lens (TL_FEATURE_UNDERWATER): where each pixel's view starts, and on
// which side of the water. With TL_FEATURE_WATERLINE the camera is at the
// surface and each pixel decides from its own point on a plane u_lens ahead
// of the camera, so one frame can show both halves with a continuous
// waterline; without it the whole frame is under water.

// Distance from the camera to where each pixel's view starts: the lens
// plane with the waterline, the camera itself without.
float underwater_start(vec3 ray)
{
#ifdef TL_FEATURE_WATERLINE
    return u_lens / max(dot(ray, u_cam_forward), 1.0e-3);
#else
    return 0.0;
#endif
}

// Height of the pixel's lens point above the surface there (negative:
// under water).
float underwater_lens_gap(vec3 ray)
{
    vec3 p = vec3(0.0, u_cam_height, 0.0) + ray * underwater_start(ray);
    return p.y - surface_height(p.xz, TL_MARCH_OCTAVES, 0.0);
}

