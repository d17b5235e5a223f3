"""Writes the clients' pictures as PNG files (standard library and numpy only), so a person
can look at what a client rendered on tessera: `$CLIENTS_OUT/<name>.png` (tools/clients.sh
sets CLIENTS_OUT to target/clients; unset, nothing is written)."""
import os
import struct
import zlib


def save(name, image):
    """Saves an (height, width, 3) uint8 array whose first row is the top of the picture."""
    out = os.environ.get("CLIENTS_OUT")
    if not out:
        return
    height, width, channels = image.shape
    assert channels == 3 and image.dtype.name == "uint8", (image.shape, image.dtype)

    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + image[y].tobytes() for y in range(height))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, name + ".png")
    with open(path, "wb") as f:
        f.write(png)
    print(f"{name}: picture in {path}")
