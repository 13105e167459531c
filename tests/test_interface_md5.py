"""Every gazebo_msgs / controller_manager_msgs / control_msgs type must match upstream's md5sum.

Run after building the workspace and sourcing devel/setup.bash:
    /usr/bin/python3 -m pytest tests/test_interface_md5.py
The expected values (tests/upstream_md5.json) are upstream's, so a match means the wire format, and with it
compatibility with tools written for Gazebo and ros_control, is unchanged.
"""
import importlib
import json
import os

import pytest

_EXPECTED_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'upstream_md5.json')
with open(_EXPECTED_FILE) as f:
    EXPECTED = json.load(f)


def load_type(type_name):
    """Return the generated class for 'pkg/Name', looking in pkg.msg then pkg.srv.

    Actions generate plain messages, so they live in pkg.msg too.
    """
    package, name = type_name.split('/')
    errors = []
    for kind in ('msg', 'srv'):
        module_name = '%s.%s' % (package, kind)
        try:
            module = importlib.import_module(module_name)
        except ImportError as error:
            errors.append('%s: %s' % (module_name, error))
            continue
        if hasattr(module, name):
            return getattr(module, name)
        errors.append('%s has no %s' % (module_name, name))
    pytest.fail('%s is missing (%s); is the workspace built and devel/setup.bash sourced?'
                % (type_name, '; '.join(errors)))


def test_expected_list_is_complete():
    packages = {name.split('/')[0] for name in EXPECTED}
    assert packages == {'gazebo_msgs', 'controller_manager_msgs', 'control_msgs'}
    assert len(EXPECTED) == 87


@pytest.mark.parametrize('type_name', sorted(EXPECTED))
def test_md5_matches_upstream(type_name):
    cls = load_type(type_name)
    assert cls._type == type_name
    assert cls._md5sum == EXPECTED[type_name], (
        '%s: md5sum %s differs from upstream %s; its definition is not field-for-field upstream'
        % (type_name, cls._md5sum, EXPECTED[type_name]))
