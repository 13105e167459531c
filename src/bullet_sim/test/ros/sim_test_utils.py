"""What bullet_sim's own rostests share besides bullet_sim_testing.gazebo: paths of their test files."""
import os

TEST_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE_DIR = os.path.dirname(TEST_DIR)


def test_path(*parts):
    return os.path.join(TEST_DIR, *parts)


def package_path(*parts):
    return os.path.join(PACKAGE_DIR, *parts)


def read(*parts):
    """A file under test/, or under the package when its path starts with 'package'."""
    path = package_path(*parts[1:]) if parts[0] == 'package' else test_path(*parts)
    with open(path) as f:
        return f.read()


def core_test_path(*parts):
    """A file under bullet_sim_core's test/ (its bad worlds, for instance)."""
    import rospkg
    return os.path.join(rospkg.RosPack().get_path('bullet_sim_core'), 'test', *parts)
