"""A seeded fuzz pass through the module: mutated material texts, MaterialX documents and dicts
either compile (and evaluate to finite numbers) or raise MaterialError, ValueError or TypeError;
nothing else, and never a crash. Seeded, so a failure reruns; about ten seconds."""

import copy
import json
import random

import numpy as np
import pytest

import matc
from conftest import BAD_INPUTS, EXAMPLE_FILES, MATERIALX

EXPECTED = (matc.MaterialError, ValueError, TypeError)
TOKENS = ['{', '}', '[', ']', '"', ':', ',', '0', '-1', '1e308', '1e-320', '2000', 'null',
          'true', '"name"', '"ior"', '"artistic"', '"spectral"', '"f82_tint"', '"\\u0000"',
          '"n"', '"k"', '"roughness"', '"color_space"', '<', '>', '/>', '="1"', '&amp;',
          'value="0.5, 0.5"', 'type="color3"', '\x00', '\ufffd']
VALUES = [None, True, "x", "", -1, 0, 0.5, 1, 1.5, 2000, 1e308, 5e-324, [], {}, [0.5],
          [0.1, 0.2], [0.1, 0.2, 0.3, 0.4], [[0.5]], {"file": "missing.csv"}, "Au", "lin_srgb"]


def _mutated_text(text, rng):
    for _ in range(rng.randint(1, 4)):
        position = rng.randrange(len(text) + 1)
        operation = rng.randrange(4)
        if operation == 0:
            text = text[:position] + rng.choice(TOKENS) + text[position:]
        elif operation == 1:
            text = text[:position] + text[position + rng.randint(1, 8):]
        elif operation == 2 and text:
            text = text[:position] + chr(rng.randrange(32, 0x250)) + text[position + 1:]
        else:
            start = rng.randrange(len(text) + 1)
            text = text[:position] + text[start:start + rng.randint(1, 16)] + text[position:]
    return text


def _mutated_dict(material, rng):
    material = copy.deepcopy(material)
    for _ in range(rng.randint(1, 3)):
        # Walk to a random container and change one member.
        node = material
        while True:
            keys = list(node) if isinstance(node, dict) else list(range(len(node)))
            if not keys:
                break
            key = rng.choice(keys)
            child = node[key]
            if isinstance(child, (dict, list)) and child and rng.random() < 0.6:
                node = child
                continue
            choice = rng.randrange(3)
            if choice == 0:
                node[key] = copy.deepcopy(rng.choice(VALUES))
            elif choice == 1 and isinstance(node, dict):
                del node[key]
            elif isinstance(node, dict):
                node[rng.choice(["unknown", "coat", "n", "k", "roughness"])] = rng.choice(VALUES)
            break
    return material


def _exercise(material):
    compiled = matc.compile(material)
    mu = np.linspace(0, 1, 9)
    values = np.concatenate([compiled.fresnel(mu), compiled.exact(mu), compiled.fbar(mu, mu)])
    assert np.all(np.isfinite(values)), compiled.name


def _seeds():
    texts = [p.read_text() for p in EXAMPLE_FILES]
    texts += [p.read_text(errors="replace") for p in sorted(BAD_INPUTS.glob("*.json"))
              if p.is_file()]
    return texts


@pytest.mark.parametrize("seed", range(4))
def test_mutated_material_texts(seed, monkeypatch):
    monkeypatch.chdir(EXAMPLE_FILES[0].parent)  # spectral files resolve against the examples
    rng = random.Random(seed)
    texts = _seeds()
    compiled = 0
    for _ in range(800):
        text = _mutated_text(rng.choice(texts), rng)
        try:
            material = matc.parse(text, path="fuzz.json")
        except EXPECTED:
            continue
        try:
            _exercise(material)
            compiled += 1
        except EXPECTED:
            pass
    assert compiled > 0  # the mutations leave some materials valid


@pytest.mark.parametrize("seed", range(2))
def test_mutated_materialx_documents(seed):
    rng = random.Random(seed)
    document = (MATERIALX / "metals.mtlx").read_text()
    for _ in range(150):
        try:
            materials = matc.parse_materialx(_mutated_text(document, rng), path="fuzz.mtlx")
        except EXPECTED:
            continue
        for material in materials:
            try:
                _exercise(material)
            except EXPECTED:
                pass


@pytest.mark.parametrize("seed", range(4))
def test_mutated_dicts(seed, monkeypatch):
    monkeypatch.chdir(EXAMPLE_FILES[0].parent)
    rng = random.Random(seed)
    dicts = [json.loads(p.read_text()) for p in EXAMPLE_FILES]
    for _ in range(500):
        try:
            _exercise(_mutated_dict(rng.choice(dicts), rng))
        except EXPECTED:
            pass
