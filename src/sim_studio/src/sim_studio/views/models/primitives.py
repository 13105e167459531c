"""Gazebo's simple shapes (the Insert toolbar's box, sphere and cylinder) as SDF: unit size,
1 kg, the solid's inertia, grey as Gazebo draws them. Pure, no ROS."""
SHAPES = {
    # name: (geometry, (ixx, iyy, izz) of a 1 kg solid, height of its centre above its base)
    "box": ("<box><size>1 1 1</size></box>", (1 / 6, 1 / 6, 1 / 6), 0.5),
    "sphere": ("<sphere><radius>0.5</radius></sphere>", (0.1, 0.1, 0.1), 0.5),
    "cylinder": ("<cylinder><radius>0.5</radius><length>1</length></cylinder>",
                 ((3 * 0.25 + 1) / 12, (3 * 0.25 + 1) / 12, 0.125), 0.5),
}

TEMPLATE = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="{name}">
    <link name="link">
      <inertial>
        <mass>1.0</mass>
        <inertia><ixx>{ixx:.6f}</ixx><ixy>0</ixy><ixz>0</ixz><iyy>{iyy:.6f}</iyy><iyz>0</iyz><izz>{izz:.6f}</izz></inertia>
      </inertial>
      <collision name="collision"><geometry>{geometry}</geometry></collision>
      <visual name="visual">
        <geometry>{geometry}</geometry>
        <material><ambient>0.7 0.7 0.7 1</ambient><diffuse>0.7 0.7 0.7 1</diffuse></material>
      </visual>
    </link>
  </model>
</sdf>
"""


def shape_model_name(shape):
    """Gazebo's name for an inserted shape: unit_box, unit_sphere, unit_cylinder."""
    check_shape(shape)
    return "unit_" + shape


def shape_sdf(shape, name):
    check_shape(shape)
    geometry, (ixx, iyy, izz), _ = SHAPES[shape]
    return TEMPLATE.format(name=name, geometry=geometry, ixx=ixx, iyy=iyy, izz=izz)


def resting_height(shape):
    """z of the shape's centre when it stands on the ground."""
    check_shape(shape)
    return SHAPES[shape][2]


def check_shape(shape):
    if shape not in SHAPES:
        raise ValueError("shape: expected one of %s, got %r" % (", ".join(SHAPES), shape))
