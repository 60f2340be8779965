#!/usr/bin/env python3
"""Independent counts for tests/io/osim_counts_test.cc.

Uses Python's xml.etree (not pugixml, not Sinew's code). Only two textual fixes are applied so a
strict XML parser accepts the files: '::' in element names becomes '__', and a bare '&' becomes
'&amp;'. Counting rules (OpenSim's layouts):
  bodies      = children of BodySet/objects, minus a 3.x body named 'ground'
  joints      = children of JointSet/objects (4.x, 3.05) + children of every Body/Joint (3.x)
  coordinates = Coordinate elements under those joints
  forces      = children of ForceSet/objects
  constraints = children of ConstraintSet/objects
  markers     = children of MarkerSet/objects
Usage: count_osim.py FILE...  (prints one line per file)
"""
import re
import sys
import xml.etree.ElementTree as ET


def load(path):
    text = open(path, 'rb').read().decode('utf-8', 'replace')
    text = re.sub(r'(</?[A-Za-z_][\w.-]*)::', r'\1__', text)
    text = re.sub(r'&(?!(amp|lt|gt|quot|apos|#\d+|#x[0-9a-fA-F]+);)', '&amp;', text)
    return ET.fromstring(text.encode('utf-8'))


def objects(model, set_tag):
    s = model.find(set_tag)
    if s is None:
        return []
    o = s.find('objects')
    return list(o) if o is not None else []


def count(path):
    root = load(path)
    model = root.find('Model')
    bodies = [b for b in objects(model, 'BodySet')]
    joints = objects(model, 'JointSet')
    for b in bodies:
        w = b.find('Joint')
        if w is not None:
            joints += list(w)
    n_bodies = len([b for b in bodies if not (b.get('name') == 'ground' and model.find('Ground') is None)])
    coords = sum(len(j.findall('.//Coordinate')) for j in joints)
    return dict(version=int(root.get('Version')), bodies=n_bodies, joints=len(joints),
                coordinates=coords, forces=len(objects(model, 'ForceSet')),
                constraints=len(objects(model, 'ConstraintSet')),
                markers=len(objects(model, 'MarkerSet')))


if __name__ == '__main__':
    for p in sys.argv[1:]:
        c = count(p)
        print('{"%s", %d, %d, %d, %d, %d, %d, %d},' % (
            p.split('tests/data/')[-1], c['version'], c['bodies'], c['joints'], c['coordinates'],
            c['forces'], c['constraints'], c['markers']))
