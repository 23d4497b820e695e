/*
 * capture_info.c — hfs_v4l2_list (capture_v4l2.h): what hfs-capture-info
 * prints, through the same ops table as the capture source, so the tests
 * run it against the fake device.
 *
 *     video /dev/video0: driver 'uvcvideo', card 'Depth Camera', bus 'usb-...'
 *       [0] 'Z16 ' (Z16, supported): Depth 16
 *           Size: Discrete 640x480
 *               Interval: Discrete 0.033s (30.000 fps)
 */
#include "capture_v4l2.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <string.h>

static void list_intervals(const hfs_v4l2_ops *ops, int fd, uint32_t fourcc, uint32_t w,
                           uint32_t h, FILE *out)
{
    for (uint32_t i = 0; i < 64; ++i) {
        struct v4l2_frmivalenum fi;
        memset(&fi, 0, sizeof fi);
        fi.index = i;
        fi.pixel_format = fourcc;
        fi.width = w;
        fi.height = h;
        if (hfs_v4l2_xioctl(ops, fd, VIDIOC_ENUM_FRAMEINTERVALS, &fi) < 0)
            return;
        if (fi.type == V4L2_FRMIVAL_TYPE_DISCRETE) {
            const double s = fi.discrete.denominator
                                 ? (double)fi.discrete.numerator / fi.discrete.denominator
                                 : 0.0;
            fprintf(out, "            Interval: Discrete %.3fs (%.3f fps)\n", s,
                    s > 0 ? 1.0 / s : 0.0);
        } else {
            const struct v4l2_fract *a = &fi.stepwise.min, *b = &fi.stepwise.max;
            fprintf(out, "            Interval: %s %u/%us - %u/%us\n",
                    fi.type == V4L2_FRMIVAL_TYPE_CONTINUOUS ? "Continuous" : "Stepwise",
                    a->numerator, a->denominator, b->numerator, b->denominator);
            return;
        }
    }
}

static void list_sizes(const hfs_v4l2_ops *ops, int fd, uint32_t fourcc, FILE *out)
{
    for (uint32_t i = 0; i < 256; ++i) {
        struct v4l2_frmsizeenum fs;
        memset(&fs, 0, sizeof fs);
        fs.index = i;
        fs.pixel_format = fourcc;
        if (hfs_v4l2_xioctl(ops, fd, VIDIOC_ENUM_FRAMESIZES, &fs) < 0)
            return;
        if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
            fprintf(out, "        Size: Discrete %ux%u\n", fs.discrete.width,
                    fs.discrete.height);
            list_intervals(ops, fd, fourcc, fs.discrete.width, fs.discrete.height, out);
        } else {
            const struct v4l2_frmsize_stepwise *s = &fs.stepwise;
            fprintf(out, "        Size: %s %ux%u - %ux%u with step %u/%u\n",
                    fs.type == V4L2_FRMSIZE_TYPE_CONTINUOUS ? "Continuous" : "Stepwise",
                    s->min_width, s->min_height, s->max_width, s->max_height, s->step_width,
                    s->step_height);
            return;
        }
    }
}

int hfs_v4l2_list(const char *path, const hfs_v4l2_ops *ops, FILE *out, hfs_error *err)
{
    if (!ops)
        ops = hfs_v4l2_sys_ops();
    const int fd = ops->open(ops->user, path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return hfs_fail(err, HFS_E_IO, "video %s: %s", path, strerror(errno));
    struct v4l2_capability cap;
    memset(&cap, 0, sizeof cap);
    if (hfs_v4l2_xioctl(ops, fd, VIDIOC_QUERYCAP, &cap) < 0) {
        const int e = errno;
        ops->close(ops->user, fd);
        return hfs_fail(err, HFS_E_INVALID, "video %s: %s", path,
                        e == ENOTTY ? "not a V4L2 device" : strerror(e));
    }
    const uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps
                                                                    : cap.capabilities;
    fprintf(out, "video %s: driver '%.16s', card '%.32s', bus '%.32s'%s%s\n", path,
            (const char *)cap.driver, (const char *)cap.card, (const char *)cap.bus_info,
            caps & V4L2_CAP_VIDEO_CAPTURE ? ", capture" : ", no capture",
            caps & V4L2_CAP_STREAMING ? ", streaming" : ", no streaming");
    for (uint32_t i = 0; i < 64; ++i) {
        struct v4l2_fmtdesc fd_;
        memset(&fd_, 0, sizeof fd_);
        fd_.index = i;
        fd_.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (hfs_v4l2_xioctl(ops, fd, VIDIOC_ENUM_FMT, &fd_) < 0)
            break;
        char cc[5];
        const char *ours = hfs_pixfmt_name(hfs_pixfmt_from_fourcc(fd_.pixelformat));
        fprintf(out, "    [%u] '%s' (%s%s): %.32s\n", i, hfs_fourcc_text(fd_.pixelformat, cc),
                ours ? ours : "not supported by hfshade", ours ? ", supported" : "",
                (const char *)fd_.description);
        list_sizes(ops, fd, fd_.pixelformat, out);
    }
    ops->close(ops->user, fd);
    return ferror(out) ? hfs_fail(err, HFS_E_IO, "hfs-capture-info: write error") : HFS_OK;
}
